// The colliders as drawn (experiments/render/collider_drawing.hpp): each analytic shape's
// surface is closed and outward with the shape's volume, and what a run writes is read back
// with its material, keyframes and removal time.
#include "experiments/render/collider_drawing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "experiments/io/atomic_file.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_geometry_observer.hpp"

namespace rice::experiments {
namespace {

/// The signed volume Σ (a · (b × c)) / 6: positive for a closed outward mesh.
double signed_volume(const grains::SurfaceMesh& m) {
  double volume = 0.0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

xpbd::Collider shaped(xpbd::ColliderShape shape, double radius = 0.0, double half_length = 0.0,
                      const xpbd::Vec3& half_extents = xpbd::Vec3::Zero()) {
  xpbd::Collider c;
  c.shape = shape;
  c.radius = radius;
  c.half_length = half_length;
  c.half_extents = half_extents;
  return c;
}

TEST(ColliderDrawing, EachShapeIsClosedOutwardWithItsVolume) {
  const xpbd::Collider box = shaped(xpbd::ColliderShape::kBox, 0.0, 0.0, xpbd::Vec3(0.03, 0.02, 0.005));
  const grains::SurfaceMesh box_mesh = collider_surface(box);
  EXPECT_NEAR(signed_volume(box_mesh), 8 * 0.03 * 0.02 * 0.005, 1e-12);
  // Flat faces: each vertex's area-weighted normal is its face's (a renderer interpolates
  // them; corners shared by a large top and a thin side bent the side's normals down).
  grains::Vertices N = grains::Vertices::Zero(box_mesh.V.rows(), 3);
  for (Eigen::Index f = 0; f < box_mesh.F.rows(); ++f) {
    const Eigen::RowVector3d a = box_mesh.V.row(box_mesh.F(f, 0)), b = box_mesh.V.row(box_mesh.F(f, 1)),
                             c = box_mesh.V.row(box_mesh.F(f, 2));
    for (int k = 0; k < 3; ++k) N.row(box_mesh.F(f, k)) += (b - a).cross(c - a);
  }
  for (Eigen::Index f = 0; f < box_mesh.F.rows(); ++f) {
    const Eigen::RowVector3d a = box_mesh.V.row(box_mesh.F(f, 0)), b = box_mesh.V.row(box_mesh.F(f, 1)),
                             c = box_mesh.V.row(box_mesh.F(f, 2));
    for (int k = 0; k < 3; ++k)
      EXPECT_GT(N.row(box_mesh.F(f, k)).normalized().dot((b - a).cross(c - a).normalized()), 0.9999) << f;
  }
  const xpbd::Collider sphere = shaped(xpbd::ColliderShape::kSphere, 0.01);
  EXPECT_NEAR(signed_volume(collider_surface(sphere)) / (4.0 / 3.0 * std::numbers::pi * 1e-6), 1.0, 0.02);
  const xpbd::Collider capsule = shaped(xpbd::ColliderShape::kCapsule, 0.01, 0.02);
  const double capsule_volume = std::numbers::pi * 1e-4 * 0.04 + 4.0 / 3.0 * std::numbers::pi * 1e-6;
  EXPECT_NEAR(signed_volume(collider_surface(capsule)) / capsule_volume, 1.0, 0.02);
  const grains::SurfaceMesh plane = collider_surface(xpbd::Collider{});
  const Eigen::Vector3d a = plane.V.row(plane.F(0, 0)), b = plane.V.row(plane.F(0, 1)), c = plane.V.row(plane.F(0, 2));
  EXPECT_GT((b - a).cross(c - a).z(), 0.0);  // the top face of the solid below z = 0
  EXPECT_THROW(collider_surface(shaped(xpbd::ColliderShape::kDistanceGrid)), std::invalid_argument);
}

// A mould's room (a cube) seen from far along +x: its walls but the one towards the eye,
// turned to face into the room, where the grains are.
TEST(ColliderDrawing, AMouldIsCutAwayTowardsTheEye) {
  const grains::SurfaceMesh room = collider_surface(shaped(xpbd::ColliderShape::kBox, 0.0, 0.0, xpbd::Vec3(1, 1, 1)));
  const grains::SurfaceMesh walls = cutaway_walls(room, Eigen::Vector3d(10, 0, 0));
  ASSERT_EQ(walls.F.rows(), 10);
  for (Eigen::Index f = 0; f < walls.F.rows(); ++f) {
    const Eigen::Vector3d a = walls.V.row(walls.F(f, 0)), b = walls.V.row(walls.F(f, 1)), c = walls.V.row(walls.F(f, 2));
    EXPECT_GT((b - a).cross(c - a).dot(-a), 0.0) << f;  // towards the centre
    EXPECT_LT(std::min({a.x(), b.x(), c.x()}), 1.0) << f;  // not the wall at x = 1, towards the eye
  }
}

TEST(ColliderDrawing, ARunsCollidersAreReadBackWithMaterialMotionAndRemoval) {
  const Scene scene = parse_scene(R"(
[[colliders]]
shape = "box"
half_extents_m = [0.03, 0.03, 0.005]
material = "wood"
removed_at_s = 2.5
keyframes = [{ time_s = 0.0, position_m = [0.0, 0.0, 0.08] }, { time_s = 2.0, position_m = [0.0, 0.0, 0.01], angle_deg = 30 }]

[[colliders]]
shape = "sphere"
radius_m = 0.01
)", "colliders.toml");
  const std::vector<ColliderDrawing> written = collider_drawings(scene);
  ASSERT_EQ(written.size(), 2u);
  const std::filesystem::path run = std::filesystem::temp_directory_path() / "rice_collider_drawing";
  std::filesystem::remove_all(run);
  write_collider_drawings(written, run);
  const std::vector<ColliderDrawing> read = read_collider_drawings(run);
  std::filesystem::remove_all(run);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].material, "wood");
  EXPECT_EQ(read[1].material, "plastic");
  EXPECT_EQ(read[0].motion.removal_time, 2.5);
  EXPECT_TRUE(std::isinf(read[1].motion.removal_time));
  EXPECT_EQ(read[0].mesh.F.rows(), written[0].mesh.F.rows());
  ASSERT_EQ(read[0].motion.motion.size(), 2u);
  const xpbd::ColliderKeyframe at = xpbd::collider_pose(read[0].motion, 1.0);
  const xpbd::ColliderKeyframe expected = xpbd::collider_pose(written[0].motion, 1.0);
  EXPECT_LT((at.translation - expected.translation).norm(), 1e-12);
  EXPECT_LT(at.rotation.angularDistance(expected.rotation), 1e-12);
  EXPECT_FALSE(xpbd::collider_present(read[0].motion, 2.5));
  EXPECT_TRUE(read_collider_drawings(run).empty());  // a run without colliders
}

TEST(ColliderDrawing, AYieldingColliderIsDrawnWhereItStoodBack) {
  // yield.csv (yield_observer.hpp) says how far the box stood back along its axis at each frame:
  // drawn there, linear between frames; a row naming a collider the run does not have is refused.
  const Scene scene = parse_scene("[[colliders]]\nshape = \"box\"\nhalf_extents_m = [0.03, 0.03, 0.005]\n"
                                  "position_m = [0.0, 0.0, 0.02]\nforce_limit_n = 1\n",
                                  "lid.toml");
  const std::filesystem::path run = std::filesystem::temp_directory_path() / "rice_yield_drawing";
  std::filesystem::remove_all(run);
  write_collider_drawings(collider_drawings(scene), run);
  const std::string header = "frame,time_s,collider,offset_m,force_n,axis_x,axis_y,axis_z\n";
  write_file_atomically(run / "yield.csv", header + "30,1.0,1,0.002,1.0,0,0,1\n45,1.5,1,0.004,1.0,0,0,1\n");
  const std::vector<ColliderDrawing> read = read_collider_drawings(run);
  ASSERT_EQ(read.size(), 1u);
  EXPECT_NEAR(collider_placement(read[0], 1.25).translation().z(), 0.023, 1e-12);
  EXPECT_NEAR(collider_placement(read[0], 2.0).translation().z(), 0.024, 1e-12);
  write_file_atomically(run / "yield.csv", header + "30,1.0,3,0.002,1.0,0,0,1\n");
  EXPECT_THROW(read_collider_drawings(run), std::runtime_error);
  std::filesystem::remove_all(run);
}

TEST(ColliderDrawing, TheBoxDrawnHoldsEveryPoseWhileThePieceIsPresent) {
  ColliderDrawing lid{collider_surface(shaped(xpbd::ColliderShape::kSphere, 0.01)), "wood", {}};
  lid.motion.motion = {{0.0, xpbd::Vec3(0.0, 0.0, 0.1)}, {1.0, xpbd::Vec3(0.0, 0.0, 0.0)}};
  lid.motion.removal_time = 2.0;
  const Eigen::AlignedBox3d late = drawn_colliders_box({lid}, {1.0, 1.5});
  EXPECT_NEAR(late.max().z(), 0.01, 1e-12);
  EXPECT_NEAR(late.min().z(), -0.01, 1e-12);
  const Eigen::AlignedBox3d all = drawn_colliders_box({lid}, {0.0, 0.5, 1.0});
  EXPECT_NEAR(all.max().z(), 0.11, 1e-12);  // its first pose, 10 cm up
  EXPECT_NEAR(all.max().x(), 0.01, 5e-4);
  EXPECT_TRUE(drawn_colliders_box({lid}, {2.0, 3.0}).isEmpty());  // removed
}

}  // namespace
}  // namespace rice::experiments
