// A mesh's vertices split along its creases for drawing (experiments/render/crease_split.hpp):
// a cube's corners become one vertex per face, so each face's interpolated normals are its own;
// a smooth capsule keeps every shared vertex; the faces and the volume stay.
#include "experiments/render/crease_split.hpp"

#include <gtest/gtest.h>

#include "experiments/render/collider_drawing.hpp"
#include "shading/curvature.hpp"

namespace rice::experiments {
namespace {

/// The unit cube with its 8 corners shared by its 12 triangles, outward.
grains::SurfaceMesh shared_cube() {
  grains::SurfaceMesh m{grains::Vertices(8, 3), grains::Triangles(12, 3)};
  for (int v = 0; v < 8; ++v) m.V.row(v) << (v & 1), ((v >> 1) & 1), ((v >> 2) & 1);
  m.F << 0, 2, 3, 0, 3, 1,  // z = 0
      4, 5, 7, 4, 7, 6,     // z = 1
      0, 1, 5, 0, 5, 4,     // y = 0
      2, 6, 7, 2, 7, 3,     // y = 1
      0, 4, 6, 0, 6, 2,     // x = 0
      1, 3, 7, 1, 7, 5;     // x = 1
  return m;
}

TEST(CreaseSplit, ACubesCornersSplitPerFaceSoEachFaceKeepsItsOwnNormal) {
  const grains::SurfaceMesh cube = shared_cube();
  // Shared, each corner's normal is the mean of three faces': (±1, ±1, ±1)/√3.
  const shading::MeshVertices shared = shading::vertex_normals(cube.V, cube.F);
  EXPECT_NEAR(std::abs(shared(0, 0)), 1.0 / std::sqrt(3.0), 1e-12);
  const grains::SurfaceMesh split = split_creases(cube);
  EXPECT_EQ(split.V.rows(), 24);  // 8 corners × 3 faces
  ASSERT_EQ(split.F.rows(), cube.F.rows());
  const shading::MeshVertices normals = shading::vertex_normals(split.V, split.F);
  for (Eigen::Index f = 0; f < split.F.rows(); ++f) {
    const Eigen::Vector3d a = split.V.row(split.F(f, 0)), b = split.V.row(split.F(f, 1)), c = split.V.row(split.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    for (int k = 0; k < 3; ++k) {
      EXPECT_LT((normals.row(split.F(f, k)).transpose() - n).norm(), 1e-12) << "face " << f;
      EXPECT_EQ(split.V.row(split.F(f, k)), cube.V.row(cube.F(f, k)));  // the same corner
    }
  }
}

TEST(CreaseSplit, ASmoothSurfaceKeepsItsSharedVertices) {
  xpbd::Collider capsule;
  capsule.shape = xpbd::ColliderShape::kCapsule;
  capsule.radius = 0.01;
  capsule.half_length = 0.02;
  const grains::SurfaceMesh smooth = collider_surface(capsule);
  const grains::SurfaceMesh split = split_creases(smooth);
  EXPECT_EQ(split.V.rows(), smooth.V.rows());
  EXPECT_EQ(split.F, smooth.F);  // each vertex one group, in the order its faces first name it
}

}  // namespace
}  // namespace rice::experiments
