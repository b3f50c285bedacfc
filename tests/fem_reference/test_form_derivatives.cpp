// One finite-difference harness for every term of the reference solver's energy (issue 3,
// §2): value → gradient and gradient → Hessian by central differences at random,
// near-degenerate and inverted states, and the per-element PSD projection.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "fem_reference/barrier_contact_form.hpp"
#include "fem_reference/constraint_potential_form.hpp"
#include "fem_reference/inertia_form.hpp"
#include "fem_reference/load_form.hpp"
#include "fem_reference/sphere_contact_form.hpp"
#include "fem_reference/strain_rate_damping_form.hpp"
#include "tests/common/finite_differences.hpp"
#include "tests/common/jittered_mesh.hpp"
#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/energy.hpp"

namespace rice::fem {
namespace {

using test_support::fd_gradient;
using test_support::fd_jacobian;
using test_support::relative_error;

// Central differences with a step of 1e-6 of the body size: truncation ~1e-12, round-off
// ~1e-10 relative, so 1e-6 separates right from wrong by orders of magnitude.
constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-6;

Positions reshape(const Eigen::VectorXd& v) {
  return Eigen::Map<const Positions>(v.data(), v.size() / 3, 3);
}
Eigen::VectorXd flatten(const Positions& x) {
  return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
}

Eigen::VectorXd gradient_of(const Form& form, const Positions& x) {
  Positions g = Positions::Zero(x.rows(), 3);
  form.add_gradient(x, 1.0, g);
  return flatten(g);
}

Eigen::MatrixXd hessian_of(const Form& form, const Positions& x, bool project) {
  const DofMap dofs(std::vector<bool>(x.rows(), false));
  SparseHessian H(dofs, {form.stencils()});
  form.add_hessian(x, 1.0, project, H);
  return Eigen::MatrixXd(H.matrix());
}

/// Checks ∇value and ∇²value of `form` at x against central differences, and that the
/// projected Hessian is PSD and equals the exact one where that is already PSD.
void check_form(const Form& form, const Positions& x, double scale) {
  SCOPED_TRACE(form.name());
  const Eigen::VectorXd x0 = flatten(x);
  const double h = kStep * scale;
  const Eigen::VectorXd g = gradient_of(form, x);
  const Eigen::VectorXd g_fd = fd_gradient([&](const Eigen::VectorXd& v) { return form.value(reshape(v)); }, x0, h);
  EXPECT_LT(relative_error(g, g_fd, 1e-12), kTolerance) << "gradient\n" << g.transpose() << "\nfd\n" << g_fd.transpose();

  const Eigen::MatrixXd H = hessian_of(form, x, false);
  const Eigen::MatrixXd H_fd = fd_jacobian([&](const Eigen::VectorXd& v) { return gradient_of(form, reshape(v)); }, x0, h);
  EXPECT_LT(relative_error(H, H_fd, 1e-12), kTolerance) << "Hessian";
  EXPECT_LT(relative_error(H, H.transpose(), 1e-12), 1e-12) << "Hessian not symmetric";

  const Eigen::MatrixXd P = hessian_of(form, x, true);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(P);
  EXPECT_GE(eigen.eigenvalues().minCoeff(), -1e-9 * std::max(1.0, P.norm())) << "projection not PSD";
}

/// A small irregular Neo-Hookean block (size 1 cm) with springs, volumes and attachments,
/// all with damping (the tets with both kinds).
xpbd::Model make_model() {
  const xpbd::TetMesh mesh = test_support::jittered_box_mesh(xpbd::Vec3(0.02, 0.01, 0.01), 2, 1, 1, 0.0);
  xpbd::Model model;
  model.particles = xpbd::make_particles(mesh, 1000.0);
  xpbd::add_neo_hookean_tets(model, mesh, xpbd::lame_from_young_poisson(1e5, 0.3), 0.01, 0.02);
  xpbd::add_edge_springs(model, mesh, 1e5, 0.01);
  xpbd::add_tet_volumes(model, mesh, 1e5, 0.01);
  model.attachments.push_back({0, xpbd::Vec3(0.001, -0.002, 0.0), 1e-4});
  model.attachments.push_back({5, xpbd::Vec3(0.02, 0.01, 0.013), 2e-4});
  model.external_forces = Positions::Constant(model.particles.size(), 3, 0.1);
  return model;
}

/// The rest shape deformed by a random affine map plus per-vertex noise of `noise` metres.
Positions deformed(const Positions& rest, double noise, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  xpbd::Mat3 A = xpbd::Mat3::Identity();
  for (int i = 0; i < 9; ++i) A.data()[i] += 0.2 * u(random);
  Positions x = rest * A.transpose();
  for (int i = 0; i < x.size(); ++i) x.data()[i] += noise * u(random);
  return x;
}

class FormDerivatives : public ::testing::TestWithParam<const char*> {};

/// Every form of the model, at the state named by the test parameter.
void check_all_forms(const Positions& x, const Positions& x_start) {
  xpbd::Model model = make_model();
  const double h = 1e-3;
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(make_constraint_form<NeoHookeanKernel>("neo-hookean", model.neo_hookean));
  forms.push_back(make_constraint_form<TetVolumeKernel>("tet volume", model.volumes));
  forms.push_back(make_constraint_form<DistanceKernel>("distance", model.distances));
  forms.push_back(make_constraint_form<AttachmentKernel>("attachment", model.attachments));
  auto step_nh = make_constraint_form<NeoHookeanKernel>("neo-hookean step", model.neo_hookean, h);
  auto step_volume = make_constraint_form<TetVolumeKernel>("tet volume step", model.volumes, h);
  auto step_distance = make_constraint_form<DistanceKernel>("distance step", model.distances, h);
  step_nh->set_targets(x_start);
  step_volume->set_targets(x_start);
  step_distance->set_targets(x_start);
  forms.push_back(std::move(step_nh));
  forms.push_back(std::move(step_volume));
  forms.push_back(std::move(step_distance));
  auto strain_rate_damping = std::make_unique<StrainRateDampingForm>(model.neo_hookean, h);
  strain_rate_damping->set_start(x_start);
  forms.push_back(std::move(strain_rate_damping));
  auto inertia = std::make_unique<InertiaForm>(model.particles.w);
  inertia->set_target(x_start);
  forms.push_back(std::move(inertia));
  forms.push_back(std::make_unique<LoadForm>(model));
  for (const auto& form : forms) check_form(*form, x, 0.01);
}

TEST(FormDerivatives, MatchFiniteDifferencesAtRandomStates) {
  const xpbd::Model model = make_model();
  for (unsigned seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE(seed);
    check_all_forms(deformed(model.particles.x, 1e-3, seed), deformed(model.particles.x, 1e-3, seed + 10));
  }
}

TEST(FormDerivatives, MatchFiniteDifferencesNearDegenerateAndInverted) {
  const xpbd::Model model = make_model();
  // Every vertex squashed onto a layer 1e-3 of the height thick: nearly flat tets.
  Positions flat = model.particles.x;
  flat.col(2) *= 1e-3;
  check_all_forms(flat, model.particles.x);
  // Mirrored through the plane z = 0: every tet inverted (det F < 0).
  Positions inverted = deformed(model.particles.x, 1e-4, 7);
  inverted.col(2) *= -1.0;
  check_all_forms(inverted, model.particles.x);
}

TEST(FormDerivatives, ContactBarrierMatchesFiniteDifferencesNearPlanesAndSpheres) {
  // Particles between 0.1 d̂ and 1.2 d̂ from the ground, a tilted half-space and a sphere
  // (d̂ = 1e-4 m): the barrier's gradient and Hessian against central differences.
  xpbd::Model model;
  model.ground = xpbd::GroundPlane{};
  const double dhat = 1e-4, radius = 1e-3;
  const xpbd::Vec3 centre(0.01, 0.0, 0.005);
  const xpbd::Vec3 tilted = xpbd::Vec3(0.3, -0.2, 1.0).normalized();
  xpbd::Collider sphere, half_space;
  sphere.shape = xpbd::ColliderShape::kSphere;
  sphere.radius = radius;
  sphere.motion[0].translation = centre;
  half_space.shape = xpbd::ColliderShape::kHalfSpace;
  half_space.motion[0].translation = xpbd::Vec3(-0.01, 0.0, 0.0);
  half_space.motion[0].rotation = xpbd::Quat::FromTwoVectors(xpbd::Vec3::UnitZ(), tilted);
  model.colliders.push_back(sphere);
  model.colliders.push_back(half_space);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> fraction(0.1, 1.2);
  std::vector<xpbd::Vec3> points;
  for (int k = 0; k < 4; ++k) {
    points.emplace_back(0.002 * k, 0.001, fraction(random) * dhat);                            // ground
    const xpbd::Vec3 out = xpbd::Vec3(1.0, 0.5 * k - 1.0, 0.7).normalized();
    points.push_back(centre + (radius + fraction(random) * dhat) * out);                     // sphere
    points.push_back(xpbd::Vec3(-0.01, 0.0, 0.0) + fraction(random) * dhat * tilted +
                     0.001 * k * tilted.cross(xpbd::Vec3::UnitX()));  // half-space
  }
  model.particles.x.resize(static_cast<int>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) model.particles.x.row(i) = points[i].transpose();
  model.particles.v = Positions::Zero(model.particles.x.rows(), 3);
  model.particles.w = Eigen::VectorXd::Ones(model.particles.x.rows());
  const BarrierContactForm barrier(model, {.activation_distance = dhat, .stiffness = 1e3});
  check_form(barrier, model.particles.x, 1e-4);
  // The barrier is infinite on contact and inside; max_step keeps a step short of it.
  Positions dx = Positions::Zero(model.particles.x.rows(), 3);
  dx(0, 2) = -1.0;  // straight down through the ground
  const double step = barrier.max_step(model.particles.x, dx);
  EXPECT_GT(step, 0.0);
  EXPECT_LT(step, model.particles.x(0, 2));
  EXPECT_TRUE(std::isfinite(barrier.value(model.particles.x + step * dx)));
  EXPECT_FALSE(std::isfinite(barrier.value(model.particles.x + 1.01 * model.particles.x(0, 2) * dx)));
}

TEST(FormDerivatives, SphereContactBarriersMatchFiniteDifferences) {
  // Two soft grains' collision spheres, one grain above the other and both above a tilted
  // half-space, every gap inside (0, d̂); particles jittered so no pair is aligned.
  const double dhat = 1e-4;
  xpbd::Model model;
  xpbd::test_support::add_grain(model, xpbd::BodyKind::kSoft, xpbd::Vec3::Zero());
  xpbd::test_support::add_grain(model, xpbd::BodyKind::kSoft,
                           xpbd::Vec3(0.3e-3, 0.2e-3, xpbd::test_support::kGrainThickness + 0.3 * dhat));
  const xpbd::Vec3 normal = xpbd::Vec3(0.02, 0.0, 1.0).normalized();
  model.colliders.push_back(xpbd::test_support::half_space(normal, -0.5 * dhat, 0.0, 0.0));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.05 * dhat, 0.05 * dhat);
  for (int i = 0; i < model.particles.size(); ++i)
    for (int c = 0; c < 3; ++c) model.particles.x(i, c) += jitter(random);
  const BarrierSettings settings{.activation_distance = dhat, .stiffness = 1e3};
  const SpherePairContactForm pairs(model, settings);
  const SpherePlaneContactForm planes(model, settings);
  ASSERT_EQ(pairs.element_count(), 100);   // 10 × 10 spheres of two bodies
  ASSERT_EQ(planes.element_count(), 20);
  ASSERT_GT(pairs.value(model.particles.x), 0.0);   // some pairs within d̂
  ASSERT_GT(planes.value(model.particles.x), 0.0);
  check_form(pairs, model.particles.x, dhat);
  check_form(planes, model.particles.x, dhat);
  // Newton and reaction: the pair forces on the two bodies cancel.
  EXPECT_LT((pairs.force_on_body(model.particles.x, 0) + pairs.force_on_body(model.particles.x, 1)).norm(),
            1e-9 * pairs.force_on_body(model.particles.x, 0).norm());
  EXPECT_GT(pairs.force_on_body(model.particles.x, 1).z(), 0.0);  // the lower grain pushes the upper up
  EXPECT_GT(planes.force_from_plane(model.particles.x, 0).dot(normal), 0.0);
  // max_step stops a step short of the spheres touching: the upper grain moved straight down.
  Positions dx = Positions::Zero(model.particles.x.rows(), 3);
  const xpbd::Body& upper = model.bodies[1];
  dx.middleRows(upper.first_particle, upper.particle_count).col(2).setConstant(-1e-3);
  const double step = pairs.max_step(model.particles.x, dx);
  EXPECT_GT(step, 0.0);
  EXPECT_TRUE(std::isfinite(pairs.value(model.particles.x + step * dx)));
  EXPECT_FALSE(std::isfinite(pairs.value(model.particles.x + dx)));  // 1 mm down: through the lower grain
  // The step is exact along the line, not a bound: it ends where some pair's gap has fallen to
  // a tenth of its start and no pair's below that.
  const auto gaps = [&](const Positions& x) {
    xpbd::Model moved = model;
    moved.particles.x = x;
    std::vector<double> g;
    for (int a = 0; a < moved.bodies[0].sphere_count(); ++a)
      for (int b = 0; b < moved.bodies[1].sphere_count(); ++b)
        g.push_back((xpbd::sphere_centre(moved, moved.bodies[0], a) - xpbd::sphere_centre(moved, moved.bodies[1], b)).norm() -
                    xpbd::sphere_radius(moved, moved.bodies[0], a) - xpbd::sphere_radius(moved, moved.bodies[1], b));
    return g;
  };
  const std::vector<double> before = gaps(model.particles.x), after = gaps(model.particles.x + step * dx);
  double smallest_ratio = INFINITY;
  for (size_t k = 0; k < before.size(); ++k) smallest_ratio = std::min(smallest_ratio, after[k] / before[k]);
  EXPECT_NEAR(smallest_ratio, 0.1, 1e-6);
  // Sliding 0.6 mm along the grain, over the lower one's spheres without closing any gap below
  // a tenth, is a whole step (a bound on the centres' motion alone allowed some 5% of it).
  dx.setZero();
  dx.middleRows(upper.first_particle, upper.particle_count).col(0).setConstant(0.6e-3);
  EXPECT_EQ(pairs.max_step(model.particles.x, dx), 1.0);
  // Colliders other than half-spaces are refused.
  xpbd::Collider ball;
  ball.shape = xpbd::ColliderShape::kSphere;
  ball.radius = 1e-3;
  model.colliders.push_back(ball);
  EXPECT_THROW(SpherePlaneContactForm(model, settings), std::invalid_argument);
}

TEST(FormDerivatives, IpcBarrierIsTwiceContinuousAtTheActivationDistance) {
  const double dhat = 2e-4;
  const BarrierValue at = ipc_barrier(dhat * (1.0 - 1e-7), dhat);
  EXPECT_NEAR(at.value, 0.0, 1e-20);
  EXPECT_NEAR(at.first, 0.0, 1e-14);
  EXPECT_NEAR(at.second, 0.0, 1e-6);  // b''(d̂) = 0: 3 (d − d̂)²/d² → 0
  EXPECT_GT(ipc_barrier(0.5 * dhat, dhat).second, 0.0);
  EXPECT_LT(ipc_barrier(0.5 * dhat, dhat).first, 0.0);
}

TEST(FormDerivatives, ElasticEnergyEqualsTheXpbdModelEnergy) {
  // One energy, two solvers: the reference's U is the XPBD model's elastic_energy.
  xpbd::Model model = make_model();
  model.particles.x = deformed(model.particles.x, 1e-3, 3);
  const double U = make_constraint_form<NeoHookeanKernel>("", model.neo_hookean)->value(model.particles.x) +
                   make_constraint_form<TetVolumeKernel>("", model.volumes)->value(model.particles.x) +
                   make_constraint_form<DistanceKernel>("", model.distances)->value(model.particles.x);
  model.attachments.clear();
  EXPECT_NEAR(U, xpbd::elastic_energy(model), 1e-12 * std::abs(U));
  const Positions gradient_expected = xpbd::elastic_energy_gradient(model);
  Positions gradient = Positions::Zero(model.particles.size(), 3);
  make_constraint_form<NeoHookeanKernel>("", model.neo_hookean)->add_gradient(model.particles.x, 1.0, gradient);
  make_constraint_form<TetVolumeKernel>("", model.volumes)->add_gradient(model.particles.x, 1.0, gradient);
  make_constraint_form<DistanceKernel>("", model.distances)->add_gradient(model.particles.x, 1.0, gradient);
  EXPECT_LT(relative_error(gradient, gradient_expected, 1e-12), 1e-12);
}

TEST(FormDerivatives, ProjectionLeavesAConvexHessianUnchanged) {
  // At rest every elastic Hessian is PSD: projection must not alter it.
  const xpbd::Model model = make_model();
  const auto form = make_constraint_form<NeoHookeanKernel>("neo-hookean", model.neo_hookean);
  const Eigen::MatrixXd exact = hessian_of(*form, model.particles.x, false);
  const Eigen::MatrixXd projected = hessian_of(*form, model.particles.x, true);
  EXPECT_LT(relative_error(exact, projected, 1e-12), 1e-10);
}

TEST(FormDerivatives, RigidConstraintIsRejectedWithItsIndex) {
  xpbd::Model model = make_model();
  model.distances[3].compliance = 0.0;
  try {
    make_constraint_form<DistanceKernel>("distance", model.distances);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("distance constraint 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rice::fem
