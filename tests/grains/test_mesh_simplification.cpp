// Edge-collapse simplification (grains/mesh_simplification.hpp): a closed sphere of 3,000
// vertices brought to at most 300 stays closed and keeps its volume; a small mesh is left as
// it is.
#include "grains/mesh_simplification.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "grains/surface_measures.hpp"

namespace rice::grains {
namespace {

/// A unit sphere as a latitude–longitude grid of `rings` × `segments` plus two poles.
SurfaceMesh uv_sphere(int rings, int segments) {
  SurfaceMesh mesh;
  mesh.V.resize(rings * segments + 2, 3);
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = M_PI * (r + 1) / (rings + 1), phi = 2.0 * M_PI * s / segments;
      mesh.V.row(r * segments + s) << std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
          std::cos(theta);
    }
  const int north = rings * segments, south = north + 1;
  mesh.V.row(north) << 0, 0, 1;
  mesh.V.row(south) << 0, 0, -1;
  std::vector<Eigen::RowVector3i> faces;
  for (int s = 0; s < segments; ++s) {
    const int t = (s + 1) % segments;
    faces.emplace_back(north, s, t);
    faces.emplace_back(south, (rings - 1) * segments + t, (rings - 1) * segments + s);
    for (int r = 0; r + 1 < rings; ++r) {
      faces.emplace_back(r * segments + s, (r + 1) * segments + s, (r + 1) * segments + t);
      faces.emplace_back(r * segments + s, (r + 1) * segments + t, r * segments + t);
    }
  }
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) mesh.F.row(static_cast<Eigen::Index>(f)) = faces[f];
  return mesh;
}

/// Every edge is shared by exactly two faces, in opposite directions.
bool closed(const SurfaceMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++directed[{mesh.F(f, k), mesh.F(f, (k + 1) % 3)}];
  for (const auto& [edge, count] : directed)
    if (count != 1 || directed.count({edge.second, edge.first}) != 1) return false;
  return true;
}

TEST(MeshSimplification, AClosedSphereKeepsItsShapeWithATenthOfItsVertices) {
  const SurfaceMesh sphere = uv_sphere(50, 60);
  ASSERT_TRUE(closed(sphere));
  const SurfaceMesh coarse = simplified(sphere, 300);
  EXPECT_LE(coarse.V.rows(), 300);
  EXPECT_GE(coarse.V.rows(), 250);
  EXPECT_TRUE(closed(coarse));
  EXPECT_NEAR(enclosed_volume(coarse), enclosed_volume(sphere), 0.03 * enclosed_volume(sphere));
  EXPECT_LT(coarse.V.rowwise().norm().maxCoeff(), 1.02);  // Lindstrom–Turk keeps the volume: 1.3% out
  EXPECT_GT(coarse.V.rowwise().norm().minCoeff(), 0.97);
}

TEST(MeshSimplification, AMeshWithFewerVerticesIsLeftAsItIs) {
  const SurfaceMesh sphere = uv_sphere(5, 6);
  const SurfaceMesh same = simplified(sphere, 100);
  EXPECT_EQ(same.V, sphere.V);
  EXPECT_EQ(same.F, sphere.F);
  EXPECT_THROW(simplified(sphere, 3), std::invalid_argument);
}

}  // namespace
}  // namespace rice::grains
