// Vertex mean curvature (shading/curvature.hpp) against spheres and ellipsoids.
#include "shading/curvature.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "tests/shading/test_meshes.hpp"

namespace rice::shading {
namespace {

using test_support::ellipsoid;
using test_support::ellipsoid_mean_curvature;
using test_support::icosphere;

// Largest relative error of H against the ellipsoid's (a sphere when a = b = c).
double worst_relative_error(int subdivisions, double a, double b, double c, const CurvatureOptions& options = {}) {
  const auto mesh = ellipsoid(subdivisions, a, b, c);
  const Eigen::VectorXd H = vertex_mean_curvature(mesh.V, mesh.F, options);
  double worst = 0.0;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    const double exact = ellipsoid_mean_curvature(mesh.V.row(v).transpose(), a, b, c);
    worst = std::max(worst, std::abs(H(v) - exact) / exact);
  }
  return worst;
}

TEST(Curvature, SphereOfRadiusRGivesOneOverR) {
  for (double r : {1e-3, 1.0, 1e3}) {  // a grain, a unit sphere, a scale far from both
    EXPECT_LT(worst_relative_error(4, r, r, r), 0.01) << "radius " << r;
  }
}

TEST(Curvature, EllipsoidMatchesItsAnalyticCurvature) {
  // A grain-like ellipsoid, 7 × 3 × 2 mm: H varies 20-fold between the tips and the sides.
  EXPECT_LT(worst_relative_error(5, 3.5e-3, 1.5e-3, 1e-3), 0.02);
}

TEST(Curvature, ErrorFallsAsTheMeshRefines) {
  // Degree 2 on the sphere: second order, each subdivision halves the edges.
  double previous = worst_relative_error(2, 1.0, 1.0, 1.0);
  for (int subdivisions : {3, 4}) {
    const double error = worst_relative_error(subdivisions, 1.0, 1.0, 1.0);
    EXPECT_LT(error, 0.3 * previous) << subdivisions << " subdivisions";
    previous = error;
  }
  // Degree 4 on the ellipsoid, once its tips are resolved.
  previous = worst_relative_error(3, 3.5e-3, 1.5e-3, 1e-3, {.jet_degree = 4});
  for (int subdivisions : {4, 5}) {
    const double error = worst_relative_error(subdivisions, 3.5e-3, 1.5e-3, 1e-3, {.jet_degree = 4});
    EXPECT_LT(error, 0.2 * previous) << subdivisions << " subdivisions";
    previous = error;
  }
}

TEST(Curvature, HigherJetDegreeIsMoreAccurateOnAFineMesh) {
  const double quadric = worst_relative_error(4, 1.0, 1.0, 1.0, {.jet_degree = 2});
  const double quartic = worst_relative_error(4, 1.0, 1.0, 1.0, {.jet_degree = 4});
  EXPECT_LT(quartic, 0.1 * quadric);
}

TEST(Curvature, InsideOutMeshHasNegativeCurvature) {
  auto mesh = icosphere(4);
  mesh.F.col(1).swap(mesh.F.col(2));
  const Eigen::VectorXd H = vertex_mean_curvature(mesh.V, mesh.F);
  EXPECT_NEAR(H.maxCoeff(), -1.0, 0.01);
  EXPECT_NEAR(H.minCoeff(), -1.0, 0.01);
}

TEST(Curvature, RefusesBadInput) {
  auto mesh = icosphere(1);
  EXPECT_THROW(vertex_mean_curvature(mesh.V, mesh.F, {.jet_degree = 5}), std::invalid_argument);
  EXPECT_THROW(vertex_mean_curvature(mesh.V, mesh.F, {.rings = 0}), std::invalid_argument);
  mesh.F(0, 0) = 1000;
  EXPECT_THROW(vertex_mean_curvature(mesh.V, mesh.F), std::invalid_argument);
  // A vertex in no triangle.
  MeshVertices V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5;
  MeshTriangles F(1, 3);
  F << 0, 1, 2;
  EXPECT_THROW(vertex_mean_curvature(V, F), std::runtime_error);
}

// A tetrahedron split off a surface: too few vertices for a jet, so the sphere of its mean
// radius about its centroid (a regular tetrahedron's vertices lie on its circumsphere).
TEST(Curvature, TinyFragmentGetsTheCurvatureOfItsSphere) {
  auto mesh = icosphere(3);
  const Eigen::Index n = mesh.V.rows();
  const double r = 0.01;
  MeshVertices V(n + 4, 3);
  V.topRows(n) = mesh.V;
  V.bottomRows(4) << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  V.bottomRows(4) *= r / std::sqrt(3.0);
  V.bottomRows(4).rowwise() += Eigen::RowVector3d(3, 0, 0);
  MeshTriangles F(mesh.F.rows() + 4, 3);
  F.topRows(mesh.F.rows()) = mesh.F;
  F.bottomRows(4) << 0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2;
  F.bottomRows(4).array() += static_cast<int>(n);
  const Eigen::VectorXd H = vertex_mean_curvature(V, F);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(H(n + k), 1.0 / r, 1e-9);
  EXPECT_NEAR(H(0), 1.0, 0.05);
}

}  // namespace
}  // namespace rice::shading
