// Finite-difference checks of every constraint kernel's gradient and Hessian, at rest, at
// random states and near degenerate ones (flat and inverted tets, nearly coincident
// particles), at metre and millimetre scale.
#include <gtest/gtest.h>

#include <random>

#include "tests/common/finite_differences.hpp"
#include "xpbd/distance_constraint.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/neo_hookean_constraints.hpp"
#include "xpbd/strain_rate_damping.hpp"
#include "xpbd/tet_volume_constraint.hpp"

namespace rice::xpbd {
namespace {

using test_support::fd_gradient;
using test_support::fd_jacobian;
using test_support::relative_error;

constexpr double kGradientTolerance = 1e-6;  // relative, central differences
constexpr double kHessianTolerance = 1e-5;

/// A constraint kernel as three functions of the stacked stencil coordinates.
struct Kernel {
  std::function<double(const Eigen::VectorXd&)> value;
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> gradient;
  std::function<Eigen::MatrixXd(const Eigen::VectorXd&)> hessian;
};

void expect_derivatives_match(const Kernel& k, const Eigen::VectorXd& x, double length_scale,
                              const std::string& where) {
  const double h = 1e-6 * length_scale;
  const Eigen::VectorXd g = k.gradient(x);
  const Eigen::VectorXd g_fd = fd_gradient(k.value, x, h);
  EXPECT_LT(relative_error(g, g_fd, 1e-12), kGradientTolerance)
      << where << "\nanalytic " << g.transpose() << "\nfd       " << g_fd.transpose();
  const Eigen::MatrixXd H = k.hessian(x);
  const Eigen::MatrixXd H_fd = fd_jacobian(k.gradient, x, h);
  EXPECT_LT(relative_error(H, H_fd, 1e-12), kHessianTolerance) << where;
  EXPECT_LT((H - H.transpose()).norm(), 1e-10 * std::max(1.0, H.norm())) << where << ": not symmetric";
}

Vec12 regular_tet(double scale) {
  return scale * stack(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.9, 0), Vec3(0.4, 0.3, 0.8));
}

/// The states every tet kernel is checked at, from a rest shape of edge length ~scale.
std::vector<std::pair<std::string, Vec12>> tet_states(double scale) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::vector<std::pair<std::string, Vec12>> states;
  const Vec12 rest = regular_tet(scale);
  states.emplace_back("rest", rest);
  for (int r = 0; r < 5; ++r) {
    Vec12 x = rest;
    for (int i = 0; i < 12; ++i) x[i] += scale * u(rng);
    states.emplace_back("random " + std::to_string(r), x);
  }
  Vec12 flat = rest;
  flat[11] = 1e-4 * scale;  // x3 almost in the plane of x0, x1, x2
  states.emplace_back("flat", flat);
  Vec12 inverted = rest;
  inverted[11] = -0.8 * scale;  // x3 mirrored through that plane
  states.emplace_back("inverted", inverted);
  return states;
}

Kernel neo_hookean_kernel(bool deviatoric, const Mat3& Dm_inv, double gamma) {
  if (deviatoric)
    return {[=](const Eigen::VectorXd& x) {
              return neo_hookean_deviatoric_value(deformation_gradient(x, Dm_inv));
            },
            [=](const Eigen::VectorXd& x) -> Eigen::VectorXd {
              return neo_hookean_deviatoric_gradient(x, Dm_inv);
            },
            [=](const Eigen::VectorXd& x) -> Eigen::MatrixXd {
              return neo_hookean_deviatoric_hessian(x, Dm_inv);
            }};
  return {[=](const Eigen::VectorXd& x) {
            return neo_hookean_hydrostatic_value(deformation_gradient(x, Dm_inv), gamma);
          },
          [=](const Eigen::VectorXd& x) -> Eigen::VectorXd {
            return neo_hookean_hydrostatic_gradient(x, Dm_inv);
          },
          [=](const Eigen::VectorXd& x) -> Eigen::MatrixXd {
            return neo_hookean_hydrostatic_hessian(x, Dm_inv);
          }};
}

class TetKernelDerivatives : public ::testing::TestWithParam<double> {};

TEST_P(TetKernelDerivatives, NeoHookeanPairMatchesFiniteDifferences) {
  const double scale = GetParam();
  const Mat3 Dm_inv = edge_matrix(regular_tet(scale)).inverse();
  const double gamma = neo_hookean_gamma(1e4, 4e4);
  for (const auto& [name, x] : tet_states(scale)) {
    expect_derivatives_match(neo_hookean_kernel(true, Dm_inv, gamma), x, scale, "C_D at " + name);
    expect_derivatives_match(neo_hookean_kernel(false, Dm_inv, gamma), x, scale, "C_H at " + name);
  }
}

TEST_P(TetKernelDerivatives, VolumeMatchesFiniteDifferences) {
  const double scale = GetParam();
  const double rest_volume = signed_volume(regular_tet(scale));
  const Kernel volume{
      [=](const Eigen::VectorXd& x) { return tet_volume_constraint_value(x, rest_volume); },
      [](const Eigen::VectorXd& x) -> Eigen::VectorXd { return tet_volume_constraint_gradient(x); },
      [](const Eigen::VectorXd& x) -> Eigen::MatrixXd { return tet_volume_constraint_hessian(x); }};
  for (const auto& [name, x] : tet_states(scale))
    expect_derivatives_match(volume, x, scale, "volume at " + name);
}

TEST_P(TetKernelDerivatives, StrainRateDampingMatchesFiniteDifferences) {
  const double scale = GetParam();
  const Mat3 Dm_inv = edge_matrix(regular_tet(scale)).inverse();
  const double mu = 3e4, lambda_lame = 5e4;
  for (const auto& [start_name, x_start] : tet_states(scale)) {
    const Mat3 F_start = deformation_gradient(x_start, Dm_inv);
    const Kernel damping{
        [=](const Eigen::VectorXd& x) {
          return strain_rate_damping_value(F_start, deformation_gradient(x, Dm_inv) - F_start, mu, lambda_lame);
        },
        [=](const Eigen::VectorXd& x) -> Eigen::VectorXd {
          return gradient_from_dF(
              strain_rate_damping_dF(F_start, deformation_gradient(x, Dm_inv) - F_start, mu, lambda_lame), Dm_inv);
        },
        [=](const Eigen::VectorXd&) -> Eigen::MatrixXd {
          return hessian_from_d2F(strain_rate_damping_d2F(F_start, mu, lambda_lame), Dm_inv);
        }};
    for (const auto& [name, x] : tet_states(scale))
      if (name != start_name)  // at x = xⁿ the gradient is zero, which a relative error cannot judge
        expect_derivatives_match(damping, x, scale, "damping from " + start_name + " at " + name);
  }
}

TEST_P(TetKernelDerivatives, VertexBlocksAreTheDiagonalBlocksOfTheStencilDerivatives) {
  // What vertex block descent reads per particle (tet_stencil.hpp) against the 12-vector
  // gradient and 12×12 Hessian, for both constraints and the damping; ∂²C_H/∂x_k² = 0.
  const double scale = GetParam();
  const Mat3 Dm_inv = edge_matrix(regular_tet(scale)).inverse();
  const double mu = 3e4, lambda_lame = 5e4;
  for (const auto& [name, x] : tet_states(scale)) {
    const Mat3 F = deformation_gradient(x, Dm_inv);
    const Vec12 gD = neo_hookean_deviatoric_gradient(x, Dm_inv);
    const Mat12 HD = neo_hookean_deviatoric_hessian(x, Dm_inv);
    const Mat12 HH = neo_hookean_hydrostatic_hessian(x, Dm_inv);
    const Mat12 HE = hessian_from_d2F(strain_rate_damping_d2F(F, mu, lambda_lame), Dm_inv);
    for (int k = 0; k < 4; ++k) {
      SCOPED_TRACE(name + ", corner " + std::to_string(k));
      const Vec3 b = stencil_weights(Dm_inv, k);
      const double tolerance = 1e-12 * HD.norm();
      EXPECT_LT((vertex_gradient(neo_hookean_deviatoric_dF(F), b) - gD.segment<3>(3 * k)).norm(), 1e-12 * gD.norm());
      const auto block = [k](const Mat12& H) { return Mat3(H.block<3, 3>(3 * k, 3 * k)); };
      EXPECT_LT((neo_hookean_deviatoric_vertex_hessian(F, b) - block(HD)).norm(), tolerance);
      EXPECT_LT(block(HH).norm(), 1e-12 * HH.norm());
      EXPECT_LT((strain_rate_damping_vertex_hessian(F, b, mu, lambda_lame) - block(HE)).norm(), 1e-12 * HE.norm());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(MetreAndMillimetre, TetKernelDerivatives, ::testing::Values(1.0, 1e-3));

TEST(StrainRateDamping, IsTheElasticStiffnessAtRestAndIgnoresRotation) {
  // At F = I the damping's Hessian in F is the Neo-Hookean pair's (the small-strain
  // stiffness, with the model's λ = λ_L + μ): the damping matrix is τ K, so each mode decays
  // at τω²/2. A rigid rotation from a rotated state costs nothing to first order.
  const double mu = 2e4, lambda_lame = 6e4, lambda = lambda_lame + mu;
  const Mat3 I = Mat3::Identity();
  const Vec9 dD = Eigen::Map<const Vec9>(neo_hookean_deviatoric_dF(I).data());
  const Vec9 dH = Eigen::Map<const Vec9>(neo_hookean_hydrostatic_dF(I).data());
  const Mat9 K = mu * (dD * dD.transpose() + neo_hookean_deviatoric_value(I) * neo_hookean_deviatoric_d2F(I)) +
                 lambda * (dH * dH.transpose() +
                           neo_hookean_hydrostatic_value(I, neo_hookean_gamma(mu, lambda)) * neo_hookean_hydrostatic_d2F(I));
  EXPECT_LT((strain_rate_damping_d2F(I, mu, lambda_lame) - K).norm(), 1e-10 * K.norm());

  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Mat3 F_start = R;
  F_start(0, 1) += 0.1;  // a sheared, rotated state
  const Mat3 W = Eigen::AngleAxisd(1e-4, Vec3(-2, 1, 0.5).normalized()).toRotationMatrix();
  const Mat3 rotation_step = (W - I) * F_start;  // F → W Fⁿ
  Mat3 shear_direction = Mat3::Zero();
  shear_direction(0, 1) = shear_direction(1, 0) = 1.0;
  const Mat3 shear_step = 1e-4 * F_start * shear_direction;
  const double rotation = strain_rate_damping_value(F_start, rotation_step, mu, lambda_lame);
  const double shear = strain_rate_damping_value(F_start, shear_step, mu, lambda_lame);
  EXPECT_GT(shear, 0.0);
  EXPECT_LT(rotation, 1e-3 * shear);  // O(θ⁴) against O(θ²)
}

Kernel distance_kernel(double rest_length) {
  return {[=](const Eigen::VectorXd& x) {
            return distance_constraint_value(x.head<3>(), x.tail<3>(), rest_length);
          },
          [](const Eigen::VectorXd& x) -> Eigen::VectorXd {
            return distance_constraint_gradient(x.head<3>(), x.tail<3>());
          },
          [](const Eigen::VectorXd& x) -> Eigen::MatrixXd {
            return distance_constraint_hessian(x.head<3>(), x.tail<3>());
          }};
}

TEST(DistanceConstraint, MatchesFiniteDifferencesAtRestRandomAndNearlyCoincident) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec6 x;
  x << 0.1, 0.2, 0.3, 1.1, 0.2, 0.3;
  expect_derivatives_match(distance_kernel(1.0), x, 1.0, "rest");
  for (int r = 0; r < 5; ++r) {
    for (int i = 0; i < 6; ++i) x[i] = u(rng);
    expect_derivatives_match(distance_kernel(0.5), x, 1.0, "random " + std::to_string(r));
  }
  x << 0.1, 0.2, 0.3, 0.1 + 1e-6, 0.2 - 2e-6, 0.3 + 1e-6;  // nearly coincident
  expect_derivatives_match(distance_kernel(1.0), x, 1e-4, "nearly coincident");
}

TEST(DistanceConstraint, CoincidentParticlesGiveFiniteValueAndZeroGradient) {
  const Vec3 p(0.3, -0.2, 0.1);
  EXPECT_DOUBLE_EQ(distance_constraint_value(p, p, 0.5), -0.5);
  EXPECT_TRUE(distance_constraint_gradient(p, p).isZero());
  EXPECT_TRUE(distance_constraint_hessian(p, p).allFinite());
}

TEST(NeoHookeanPair, IsStressFreeAtRestThoughNeitherConstraintIsZero) {
  const double mu = 2e4, lambda = 9e4;
  const Mat3 I = Mat3::Identity();
  EXPECT_NEAR(neo_hookean_deviatoric_value(I), std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(neo_hookean_hydrostatic_value(I, neo_hookean_gamma(mu, lambda)), -mu / lambda, 1e-15);
  // ∂U/∂F = μ V C_D ∂C_D/∂F + λ V C_H ∂C_H/∂F vanishes at F = I (V = 1 here).
  const Mat3 dUdF = mu * neo_hookean_deviatoric_value(I) * neo_hookean_deviatoric_dF(I) +
                    lambda * neo_hookean_hydrostatic_value(I, neo_hookean_gamma(mu, lambda)) *
                        neo_hookean_hydrostatic_dF(I);
  EXPECT_LT(dUdF.norm(), 1e-10 * mu);
  // Rest energy density is what the pair stores at F = I.
  EXPECT_NEAR(0.5 * mu * 3.0 + 0.5 * lambda * (mu / lambda) * (mu / lambda),
              neo_hookean_rest_energy_density(mu, lambda), 1e-9 * mu);
}

TEST(NeoHookeanPair, SmallStrainEnergyIsLinearElasticityWithTheGivenLameParameters) {
  // The pair linearises to Lamé (μ, λ_energy − μ); the model builder compensates, so that
  // U((I + tε)X) / t² → V (μ ε:ε + λ/2 (tr ε)²) with the (μ, λ) of E and ν. Without the
  // compensation a ν = 0.3 body is 10% too soft (caught by the cantilever validation).
  const TetMesh mesh = make_box_tet_mesh(Vec3(0.02, 0.01, 0.015), 2, 1, 1);
  const LameParameters lame = lame_from_young_poisson(1e6, 0.3);
  Model model;
  model.particles = make_particles(mesh, 1000.0);
  add_neo_hookean_tets(model, mesh, lame);
  Mat3 strain;
  strain << 0.3, 0.1, -0.2, 0.1, -0.5, 0.25, -0.2, 0.25, 0.4;
  const double t = 1e-5, volume = 0.02 * 0.01 * 0.015;
  model.particles.x = mesh.V * (Mat3::Identity() + t * strain).transpose();
  const double expected = volume * (lame.mu * strain.squaredNorm() +
                                    0.5 * lame.lambda * strain.trace() * strain.trace());
  EXPECT_NEAR(elastic_energy(model) / (t * t), expected, 1e-4 * expected);
}

}  // namespace
}  // namespace rice::xpbd
