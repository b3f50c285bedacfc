// The corotated pair (corotated_constraints.hpp): its polar rotation, the warm-started
// rotation extraction, finite-difference checks of ∂R/∂F, ∂C_D/∂F and ∂²C_D/∂F² at random,
// flat and inverted F, and the material it makes: zero at every rotation, the same small-strain
// energy as the stable Neo-Hookean pair, and an energy gradient that matches its energy.
#include <gtest/gtest.h>

#include <random>

#include "tests/common/finite_differences.hpp"
#include "xpbd/corotated_constraints.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/model.hpp"
#include "xpbd/tet_constraint_pair.hpp"

namespace rice::xpbd {
namespace {

using test_support::fd_gradient;
using test_support::fd_jacobian;
using test_support::relative_error;

Eigen::VectorXd vec(const Mat3& F) { return Eigen::Map<const Vec9>(F.data()); }
Mat3 unvec(const Eigen::VectorXd& f) { return Eigen::Map<const Mat3>(f.data()); }

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

/// Deformation gradients to check at: stretched and rotated, nearly flat, and inverted.
std::vector<std::pair<std::string, Mat3>> deformations() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  std::vector<std::pair<std::string, Mat3>> states;
  for (int r = 0; r < 5; ++r) {
    Mat3 S = Mat3::Identity();
    for (int i = 0; i < 9; ++i) S(i / 3, i % 3) += u(rng);
    states.emplace_back("random " + std::to_string(r), random_rotation(rng) * S);
  }
  const Mat3 Q = random_rotation(rng);
  states.emplace_back("flat", Q * Vec3(1.2, 0.9, 1e-3).asDiagonal() * random_rotation(rng));
  states.emplace_back("inverted", Q * Vec3(1.1, 0.8, -0.3).asDiagonal() * random_rotation(rng));
  return states;
}

TEST(CorotatedPair, PolarRotationIsTheProperRotationThatMakesRtFSymmetric) {
  for (const auto& [where, F] : deformations()) {
    const Mat3 R = polar_rotation(F);
    EXPECT_LT((R.transpose() * R - Mat3::Identity()).norm(), 1e-12) << where;
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12) << where;
    const Mat3 S = R.transpose() * F;
    EXPECT_LT((S - S.transpose()).norm(), 1e-12) << where;
  }
}

TEST(CorotatedPair, WarmStartedExtractionConvergesToThePolarRotation) {
  std::mt19937 rng(5);
  for (const auto& [where, F] : deformations()) {
    if (F.determinant() < 0.1) continue;  // from far away, an inverted F may settle elsewhere
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    refine_polar_rotation(F, q, 100);
    EXPECT_LT((q.toRotationMatrix() - polar_rotation(F)).norm(), 1e-7) << where;
  }
  // Warm-started from the last substep's rotation, a small change takes a few iterations.
  const Mat3 F0 = random_rotation(rng) * Vec3(1.1, 0.95, 0.9).asDiagonal();
  Eigen::Quaterniond q(polar_rotation(F0));
  const Mat3 F1 = Eigen::AngleAxisd(0.01, Vec3::UnitY()).toRotationMatrix() * F0 * 1.01;
  refine_polar_rotation(F1, q, 2);
  EXPECT_LT((q.toRotationMatrix() - polar_rotation(F1)).norm(), 1e-9);
  // An inverted F warm-started from nearby stays on the rotation-variant polar rotation.
  for (const auto& [where, F] : deformations()) {
    Eigen::Quaterniond near(Eigen::AngleAxisd(0.05, Vec3::UnitX()).toRotationMatrix() * polar_rotation(F));
    refine_polar_rotation(F, near, 100);
    EXPECT_LT((near.toRotationMatrix() - polar_rotation(F)).norm(), 1e-7) << where;
  }
}

TEST(CorotatedPair, DerivativesMatchFiniteDifferences) {
  const auto C = [](const Eigen::VectorXd& f) {
    const Mat3 F = unvec(f);
    return corotated_deviatoric_value(F, polar_rotation(F));
  };
  const auto dC = [](const Eigen::VectorXd& f) -> Eigen::VectorXd {
    const Mat3 F = unvec(f);
    return vec(corotated_deviatoric_dF(F, polar_rotation(F)));
  };
  const auto R = [](const Eigen::VectorXd& f) -> Eigen::VectorXd { return vec(polar_rotation(unvec(f))); };
  for (const auto& [where, F] : deformations()) {
    const double h = 1e-6;
    EXPECT_LT(relative_error(dC(vec(F)), fd_gradient(C, vec(F), h), 1e-12), 1e-6) << where;
    EXPECT_LT(relative_error(polar_rotation_dF(F), fd_jacobian(R, vec(F), h), 1e-12), 1e-5) << where;
    EXPECT_LT(relative_error(corotated_deviatoric_d2F(F), fd_jacobian(dC, vec(F), h), 1e-12), 1e-5) << where;
  }
}

TEST(CorotatedPair, EveryRotationIsAtRestWithBothConstraintsZero) {
  std::mt19937 rng(11);
  NeoHookeanTet t{};
  t.mu = 1e5;
  t.lambda = 2e5;
  t.rest_volume = 1e-9;
  t.material = TetMaterial::kCorotated;
  for (int r = 0; r < 5; ++r) {
    const TetConstraintPair p = tet_constraint_pair(t, random_rotation(rng));
    EXPECT_LT(p.C.cwiseAbs().maxCoeff(), 1e-13);
  }
  EXPECT_EQ(t.rest_energy(), 0.0);
}

/// A two-tet-wide box of either material, with energy U(x).
Model box_model(TetMaterial material, const TetMesh& mesh, const LameParameters& lame) {
  Model model;
  model.particles = make_particles(mesh, 1000.0);
  add_neo_hookean_tets(model, mesh, lame, 0.0, 0.0, material);
  return model;
}

TEST(CorotatedPair, SmallStrainEnergyIsTheNeoHookeanPairsAndLinearElasticity) {
  // Both pairs linearise to V (μ ε:ε + λ/2 (tr ε)²), whatever rotation the body has.
  const TetMesh mesh = make_box_tet_mesh(Vec3(0.02, 0.01, 0.015), 2, 1, 1);
  const LameParameters lame = lame_from_young_poisson(1e6, 0.3);
  Mat3 strain;
  strain << 0.3, 0.1, -0.2, 0.1, -0.5, 0.25, -0.2, 0.25, 0.4;
  const double t = 1e-5, volume = 0.02 * 0.01 * 0.015;
  const double expected = volume * (lame.mu * strain.squaredNorm() + 0.5 * lame.lambda * strain.trace() * strain.trace());
  std::mt19937 rng(2);
  const Mat3 Q = random_rotation(rng);
  for (const TetMaterial material : {TetMaterial::kCorotated, TetMaterial::kStableNeoHookean}) {
    Model model = box_model(material, mesh, lame);
    model.particles.x = mesh.V * (Q * (Mat3::Identity() + t * strain)).transpose();
    EXPECT_NEAR(elastic_energy(model) / (t * t), expected, 1e-4 * expected) << static_cast<int>(material);
  }
}

TEST(CorotatedPair, EnergyGradientMatchesFiniteDifferencesOfTheEnergy) {
  const TetMesh mesh = make_box_tet_mesh(Vec3(2e-3, 1e-3, 1e-3), 2, 1, 1);
  Model model = box_model(TetMaterial::kCorotated, mesh, lame_from_young_poisson(1e5, 0.3));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2e-4, 2e-4);
  for (int i = 0; i < model.particles.x.size(); ++i) model.particles.x.data()[i] += u(rng);
  const Eigen::VectorXd x0 = Eigen::Map<const Eigen::VectorXd>(model.particles.x.data(), model.particles.x.size());
  const auto U = [&](const Eigen::VectorXd& x) {
    Model m = model;
    m.particles.x = Eigen::Map<const Positions>(x.data(), model.particles.x.rows(), 3);
    return elastic_energy(m);
  };
  const Positions g = elastic_energy_gradient(model);
  const Eigen::VectorXd g_vec = Eigen::Map<const Eigen::VectorXd>(g.data(), g.size());
  EXPECT_LT(relative_error(g_vec, fd_gradient(U, x0, 1e-9), 1e-12), 1e-5);
}

TEST(CorotatedPair, NeedsAPositiveLameLambda) {
  const TetMesh mesh = make_box_tet_mesh(Vec3(1e-3, 1e-3, 1e-3), 1, 1, 1);
  Model model;
  model.particles = make_particles(mesh, 1000.0);
  EXPECT_THROW(add_neo_hookean_tets(model, mesh, lame_from_young_poisson(1e5, 0.0), 0.0, 0.0, TetMaterial::kCorotated),
               std::invalid_argument);
}

}  // namespace
}  // namespace rice::xpbd
