// The translucent rice model's pieces: the τ(d, cos θ) table and its least-squares fit
// (shading/translucency.hpp), a mesh's thickness and outer surface (shading/thickness.hpp),
// normals smoothed at the scale light averages over (shading/smooth_normals.hpp), and the
// material that adds τ to the CDRF (shading/material.hpp).
#include "shading/translucency.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "shading/material.hpp"
#include "shading/render_scene.hpp"
#include "shading/smooth_normals.hpp"
#include "shading/thickness.hpp"
#include "tests/shading/test_meshes.hpp"

namespace rice::shading {
namespace {

// τ = 0.1 + 0.02 d/mm − 0.05 cos θ + 0.01 (d/mm) cos θ: bilinear, so a table holds it exactly.
double bilinear_tau(double d, double c) { return 0.1 + 20.0 * d - 0.05 * c + 10.0 * d * c; }

TEST(TranslucencyTable, ReadsItsNodesAndIsBilinearBetween) {
  std::vector<double> values;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) values.push_back(bilinear_tau(1e-3 * i, -1.0 + j));
  const TranslucencyTable table(3e-3, 4, 3, values);
  EXPECT_DOUBLE_EQ(table(2e-3, 0.0), bilinear_tau(2e-3, 0.0));
  EXPECT_NEAR(table(1.3e-3, 0.4), bilinear_tau(1.3e-3, 0.4), 1e-12);
  EXPECT_NEAR(table(9e-3, -2.0), bilinear_tau(3e-3, -1.0), 1e-12);  // clamped to the grid
  const TranslucencyTable::Stencil s = table.stencil(0.7e-3, -0.3);
  EXPECT_NEAR(s.weight[0] + s.weight[1] + s.weight[2] + s.weight[3], 1.0, 1e-12);
  EXPECT_THROW(TranslucencyTable(3e-3, 4, 3, std::vector<double>(11)), std::invalid_argument);
  EXPECT_THROW(TranslucencyTable(0.0, 4, 3, values), std::invalid_argument);
}

TEST(TranslucencyTable, BlendsNodeByNode) {
  const TranslucencyTable a(1e-3, 2, 2, {0, 0, 0, 0}), b(1e-3, 2, 2, {1, 2, 3, 4});
  EXPECT_DOUBLE_EQ(TranslucencyTable::blend(a, b, 0.25).values()[3], 1.0);
  EXPECT_THROW(TranslucencyTable::blend(a, TranslucencyTable(2e-3, 2, 2, {0, 0, 0, 0}), 0.5), std::invalid_argument);
}

// Noisy samples of a bilinear τ: the fit recovers it within the noise's effect on the mean.
TEST(TranslucencyFit, RecoversATableFromNoisySamples) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> d(0.0, 4e-3), c(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<TranslucencySample> samples;
  for (int k = 0; k < 20000; ++k) {
    const double dk = d(rng), ck = c(rng);
    samples.push_back({ck, dk, bilinear_tau(dk, ck) + noise(rng), 1.0});
  }
  const TranslucencyTable fit = fit_translucency(samples, 4e-3, 9, 9, 1e-6);
  for (const double dk : {0.0, 1e-3, 2.5e-3, 4e-3})
    for (const double ck : {-1.0, -0.3, 0.5, 1.0}) EXPECT_NEAR(fit(dk, ck), bilinear_tau(dk, ck), 3e-3) << dk << " " << ck;
  EXPECT_THROW(fit_translucency({}, 4e-3, 9, 9, 1e-6), std::invalid_argument);
}

// With no samples reading half the grid, the smoothing carries the fitted plane over it.
TEST(TranslucencyFit, SmoothingFillsNodesNoSampleReads) {
  std::vector<TranslucencySample> samples;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const double dk = 2e-3 * i / 20.0, ck = -1.0 + 2.0 * j / 20.0;  // d ≤ 2 mm only
      samples.push_back({ck, dk, bilinear_tau(dk, ck), 1.0});
    }
  const TranslucencyTable fit = fit_translucency(samples, 4e-3, 9, 5, 1e-3);
  EXPECT_NEAR(fit(4e-3, 1.0), bilinear_tau(4e-3, 1.0), 2e-3);
}

TEST(Thickness, OfASphereIsItsDiameterThroughAPoreToo) {
  const test_support::TestMesh solid = test_support::icosphere(3);
  const Eigen::VectorXd d = vertex_thickness(2e-3 * solid.V, solid.F);
  EXPECT_NEAR(d.minCoeff(), 4e-3, 4e-5);
  EXPECT_NEAR(d.maxCoeff(), 4e-3, 4e-5);
  const test_support::TestMesh hollow = test_support::hollow_sphere(3, 2e-3, 1e-3);
  const Eigen::VectorXd dh = vertex_thickness(hollow.V, hollow.F);
  const std::vector<bool> out = vertex_sees_out(hollow.V, hollow.F);
  const Eigen::Index outer = solid.V.rows();
  for (Eigen::Index v = 0; v < outer; ++v) {
    EXPECT_NEAR(dh(v), 4e-3, 4e-5) << v;  // across the pore, to the far side
    EXPECT_TRUE(out[v]) << v;
  }
  for (Eigen::Index v = outer; v < hollow.V.rows(); ++v) {
    EXPECT_NEAR(dh(v), 1e-3, 2e-5) << v;  // the pore's wall: the shell behind it
    EXPECT_FALSE(out[v]) << v;
  }
}

// Bumps a tenth of the radius across, on a sphere: the smoothed normals lie closer to the
// sphere's than the mesh's own, and a smooth sphere keeps its normals.
TEST(SmoothedNormals, FollowTheSurfaceUnderItsBumps) {
  test_support::TestMesh bumpy = test_support::icosphere(4);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (Eigen::Index v = 0; v < bumpy.V.rows(); ++v) bumpy.V.row(v) *= 1.0 + jitter(rng);
  const auto mean_angle = [&](const MeshVertices& N) {
    double sum = 0.0;
    for (Eigen::Index v = 0; v < N.rows(); ++v) sum += std::acos(std::clamp(N.row(v).dot(bumpy.V.row(v).normalized()), -1.0, 1.0));
    return sum / static_cast<double>(N.rows());
  };
  const double raw = mean_angle(vertex_normals(bumpy.V, bumpy.F));
  const double smoothed = mean_angle(smoothed_vertex_normals(bumpy.V, bumpy.F, 0.2));
  EXPECT_LT(smoothed, 0.4 * raw) << raw << " " << smoothed;
  const test_support::TestMesh sphere = test_support::icosphere(3);
  const MeshVertices N = smoothed_vertex_normals(sphere.V, sphere.F, 0.3);
  for (Eigen::Index v = 0; v < N.rows(); ++v) EXPECT_GT(N.row(v).dot(sphere.V.row(v)), 0.9999) << v;
  EXPECT_EQ(smoothed_vertex_normals(sphere.V, sphere.F, 0.0), vertex_normals(sphere.V, sphere.F));
  EXPECT_THROW(smoothed_vertex_normals(sphere.V, sphere.F, -1.0), std::invalid_argument);
}

// The smoothing's hash grid finds every vertex of the ball and its tabulated Gaussian is the
// Gaussian: on a bumpy sphere of 10,242 vertices it equals the sum over all vertex pairs,
// written out here, to a thousandth of a degree in the normals and, in the curvature, to 1e-4
// of the jitter's noise the smoothing leaves.
TEST(SmoothedNormals, EqualTheSumOverAllVertexPairs) {
  test_support::TestMesh bumpy = test_support::icosphere(5);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (Eigen::Index v = 0; v < bumpy.V.rows(); ++v) bumpy.V.row(v) *= 1.0 + jitter(rng);
  const MeshVertices& V = bumpy.V;
  MeshVertices weighted = MeshVertices::Zero(V.rows(), 3);  // Σ of the faces' cross products
  for (Eigen::Index f = 0; f < bumpy.F.rows(); ++f) {
    const Eigen::RowVector3d a = V.row(bumpy.F(f, 0)), b = V.row(bumpy.F(f, 1)), c = V.row(bumpy.F(f, 2));
    for (int k = 0; k < 3; ++k) weighted.row(bumpy.F(f, k)) += (b - a).cross(c - a);
  }
  const MeshVertices unit = vertex_normals(V, bumpy.F);
  const Eigen::VectorXd H = vertex_mean_curvature(V, bumpy.F);
  const double radius = 0.5;
  const MeshVertices N = smoothed_vertex_normals(V, bumpy.F, radius);
  const Eigen::VectorXd smoothed_H = smoothed_vertex_values(V, bumpy.F, H, radius);
  double worst_degrees = 0.0, error_H = 0.0, left_H = 0.0;  // Σ squares: the difference, the noise left
  for (Eigen::Index v = 0; v < V.rows(); v += 7) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    double value = 0.0, weight = 0.0;
    for (Eigen::Index u = 0; u < V.rows(); ++u) {
      const double d2 = (V.row(u) - V.row(v)).squaredNorm();
      if (d2 > radius * radius || unit.row(u).dot(unit.row(v)) <= 0.0) continue;
      const double w = std::exp(-d2 / (2.0 * 0.25 * radius * radius));  // s = radius / 2
      sum += w * weighted.row(u);
      value += w * weighted.row(u).norm() * H(u);
      weight += w * weighted.row(u).norm();
    }
    const double cosine = std::clamp(N.row(v).dot(sum.normalized()), -1.0, 1.0);
    worst_degrees = std::max(worst_degrees, std::acos(cosine) * 180.0 / std::numbers::pi);
    error_H += std::pow(smoothed_H(v) - value / weight, 2);
    left_H += std::pow(value / weight - 1.0, 2);
  }
  EXPECT_LT(worst_degrees, 1e-3);
  EXPECT_LT(error_H, 1e-8 * left_H);  // RMS: 1e-4 of the jitter's curvature the smoothing leaves
}

// The curvature of a bumpy sphere, averaged over the same ball, lies closer to the sphere's
// 1/r than the mesh's own; a constant stays constant; a shading normal set on a prototype is
// the one a hit reads.
TEST(SmoothedCurvature, FollowsTheSurfaceUnderItsBumpsAndTheSceneShadesWithIt) {
  test_support::TestMesh bumpy = test_support::icosphere(4);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (Eigen::Index v = 0; v < bumpy.V.rows(); ++v) bumpy.V.row(v) *= 1.0 + jitter(rng);
  const Eigen::VectorXd H = vertex_mean_curvature(bumpy.V, bumpy.F);
  const Eigen::VectorXd smoothed = smoothed_vertex_values(bumpy.V, bumpy.F, H, 0.3);
  const double raw_error = (H.array() - 1.0).matrix().norm(), smoothed_error = (smoothed.array() - 1.0).matrix().norm();
  EXPECT_LT(smoothed_error, 0.3 * raw_error) << raw_error << " " << smoothed_error;
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(bumpy.V.rows());
  EXPECT_LT((smoothed_vertex_values(bumpy.V, bumpy.F, ones, 0.3) - ones).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_THROW(smoothed_vertex_values(bumpy.V, bumpy.F, Eigen::VectorXd::Ones(3), 0.3), std::invalid_argument);

  RenderScene scene;
  const int prototype = scene.add_prototype(bumpy.V, bumpy.F);
  const MeshVertices up = MeshVertices::Zero(bumpy.V.rows(), 3).rowwise() + Eigen::RowVector3d(0, 0, 1);
  scene.set_shading_normals(prototype, up);
  EXPECT_THROW(scene.set_shading_normals(prototype, up.topRows(3)), std::invalid_argument);
  scene.add_instance(prototype, Eigen::Affine3d::Identity(), 0);
  scene.commit();
  const auto hit = scene.intersect({{2, 0.1f, 0.2f}, {-1, 0, 0}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_GT(hit->shading_normal.z(), 0.9999f);
  EXPECT_LT(hit->geometric_normal.z(), 0.5f);
}

TEST(TranslucentRice, AddsTauOverPiInTheAlbedosColourAndIsTheCdrfWithoutIt) {
  const CdrfTable cdrf(65, 33);
  Material m{.kind = MaterialKind::kRice, .albedo = Color(0.8f, 0.7f, 0.6f), .sigma0 = 1e-4};
  const Eigen::Vector3f n(0, 0, 1), wo(0, 0, 1), wi = Eigen::Vector3f(1, 0, -1).normalized();
  const Color paper = diffuse_term(m, cdrf, n, wo, wi, 500.0, 2e-3);
  EXPECT_NEAR(paper.x(), 0.8 * cdrf(wi.z(), 1e-4 * 500.0) / std::numbers::pi, 1e-7);
  m.translucency = std::make_shared<TranslucencyTable>(4e-3, 2, 2, std::vector<double>{0.2, 0.2, 0.0, 0.0});
  const Color translucent = diffuse_term(m, cdrf, n, wo, wi, 500.0, 2e-3);  // τ = 0.1 at d = 2 mm
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(translucent[k] - paper[k], m.albedo[k] / m.albedo.mean() * 0.1 / std::numbers::pi, 1e-6) << k;
}

}  // namespace
}  // namespace rice::shading
