// The chawan as a mesh collider: its OpenVDB distance grid reads the right distances and
// signs, and a grain dropped into it at 30 fps comes to rest on its inside surface.
#include <gtest/gtest.h>

#include "experiments/scene/collider_grid.hpp"
#include "grains/chawan.hpp"
#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/solver.hpp"

namespace rice {
namespace {

class GrainInBowl : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    grid_ = new auto(std::make_shared<const xpbd::DistanceGrid>(
        experiments::distance_grid_of(grains::make_chawan(shape_), kSpacing, 0.005)));
  }
  static void TearDownTestSuite() { delete grid_; }
  static constexpr double kSpacing = 1e-3;
  static inline const grains::ChawanShape shape_{};
  static inline std::shared_ptr<const xpbd::DistanceGrid>* grid_ = nullptr;
  double inside_bottom() const { return shape_.height - shape_.inner_depth; }
};

TEST_F(GrainInBowl, TheGridReadsDistancesAndSigns) {
  xpbd::validate(**grid_);
  // 2 mm above the inside bottom, on the axis: outside the material, 2 mm from it.
  const xpbd::GridSample above = xpbd::sample(**grid_, xpbd::Vec3(0.0, 0.0, inside_bottom() + 2e-3));
  EXPECT_NEAR(above.distance, 2e-3, 0.3 * kSpacing);
  EXPECT_GT(above.gradient.z(), 0.95);
  // In the wall under the rim: inside the material.
  const double r = shape_.rim_radius - 0.5 * shape_.wall_thickness;
  EXPECT_LT(xpbd::sample(**grid_, xpbd::Vec3(r, 0.0, shape_.height - 2e-3)).distance, -1e-3);
  // In the solid foot.
  EXPECT_LT(xpbd::sample(**grid_, xpbd::Vec3(0.0, 0.0, 0.5 * inside_bottom())).distance, -2e-3);
}

TEST_F(GrainInBowl, ADroppedGrainRestsOnTheInsideBottom) {
  xpbd::Model model;
  const int grain = xpbd::test_support::add_grain(model, xpbd::BodyKind::kRigid,
                                             xpbd::Vec3(0.004, -0.0015, inside_bottom() + 0.03));
  xpbd::Collider bowl;
  bowl.shape = xpbd::ColliderShape::kDistanceGrid;
  bowl.grid = *grid_;
  bowl.static_friction = 0.5;
  bowl.dynamic_friction = 0.4;
  model.colliders.push_back(bowl);
  xpbd::SolverSettings settings;
  settings.time_step = 1.0 / 30.0;
  settings.substeps = 20;
  settings.iterations = 1;
  xpbd::Solver solver(model, settings);
  for (int frame = 0; frame < 60; ++frame) solver.step();
  // It rests on the inside surface: its spheres' smallest clearance to the bowl is zero, to a
  // fraction of a voxel (the bottom is curved, so it may stop where friction holds it).
  double clearance = INFINITY;
  const xpbd::Body& body = model.bodies[grain];
  for (int s = 0; s < body.sphere_count(); ++s)
    clearance = std::min(clearance, xpbd::sample(**grid_, xpbd::sphere_centre(model, body, s)).distance - body.radii[s]);
  EXPECT_NEAR(clearance, 0.0, 0.3 * kSpacing);
  const xpbd::Vec3 centre = xpbd::test_support::body_centre(model, grain);
  EXPECT_LT(centre.z(), inside_bottom() + 0.01);  // at the bottom, not caught on the wall
  EXPECT_LT(centre.head<2>().norm(), 0.02);
  EXPECT_LT(model.rigid_bodies[0].v.norm(), 1e-3);
}

}  // namespace
}  // namespace rice
