// The reference solver's Newton loop and boundary conditions: analytic static balances,
// pinned DOFs left out, the regularisation fall-back on a singular Hessian, assembly with
// pinned rows removed, and clear errors for models it cannot solve.
#include <gtest/gtest.h>

#include "fem_reference/implicit_solver.hpp"
#include "xpbd/solver.hpp"
#include "tests/common/finite_differences.hpp"
#include "tests/common/jittered_mesh.hpp"
#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/energy.hpp"

namespace rice::fem {
namespace {

using xpbd::Vec3;

xpbd::Model block(int n, double young = 1e5) {
  const xpbd::TetMesh mesh = test_support::jittered_box_mesh(Vec3::Constant(0.01), n, n, n, 0.15, 3);
  xpbd::Model model;
  model.particles = xpbd::make_particles(mesh, 1000.0);
  xpbd::add_neo_hookean_tets(model, mesh, xpbd::lame_from_young_poisson(young, 0.3));
  return model;
}

TEST(ImplicitSolver, CompliantAttachmentSagsByAlphaTimesWeight) {
  // One particle hanging from a compliant attachment: static balance x − p = α m g exactly.
  xpbd::Model model;
  model.particles.x = Positions::Zero(1, 3);
  model.particles.v = Positions::Zero(1, 3);
  model.particles.w = Eigen::VectorXd::Constant(1, 1.0 / 0.2);
  model.attachments.push_back({0, Vec3(0.0, 0.0, 1.0), 1e-3});
  ImplicitSolver solver(model, {});
  EXPECT_TRUE(solver.solve_static().converged);
  const Vec3 expected = Vec3(0.0, 0.0, 1.0) + 1e-3 * 0.2 * model.gravity;
  EXPECT_LT((model.particles.x.row(0).transpose() - expected).norm(), 1e-12);
}

TEST(ImplicitSolver, PinnedAndRigidlyAttachedParticlesStayWhereTheyAre) {
  xpbd::Model model = block(2);
  xpbd::pin_particles(model, {0, 1, 2});
  const Vec3 target(0.02, 0.0, 0.0);
  model.attachments.push_back({8, target, 0.0});
  const Positions start = model.particles.x;
  ImplicitSolver solver(model, {.time_step = 1e-3, .newton = {}});
  for (int s = 0; s < 20; ++s) solver.step();
  EXPECT_TRUE(solver.report().converged);
  for (int i : {0, 1, 2}) EXPECT_EQ(model.particles.x.row(i), start.row(i));
  EXPECT_EQ(model.particles.x.row(8).transpose(), target);
  EXPECT_GT((model.particles.x - start).rowwise().norm().maxCoeff(), 1e-4) << "the rest moved";
}

TEST(ImplicitSolver, FreeBodyRelaxesThroughItsSingularHessian) {
  // No pins, no loads: the Hessian has six rigid null modes, so CHOLMOD needs the diagonal
  // shift of the fall-back. The body must still return to a stress-free shape.
  xpbd::Model model = block(2);
  model.gravity.setZero();
  for (int i = 0; i < model.particles.size(); ++i) model.particles.x.row(i) *= (i % 3 == 0) ? 1.05 : 0.97;
  ImplicitSolver solver(model, {.newton = {.tolerance = 1e-9, .max_iterations = 200}});
  const NewtonReport report = solver.solve_static();
  EXPECT_TRUE(report.converged) << report.iterations << " iterations, |g| " << report.gradient_norm;
  EXPECT_GT(report.regularized_steps, 0);
  EXPECT_LT(xpbd::elastic_energy(model), 1e-12);
}

TEST(ImplicitSolver, NewtonConvergesFastOnALargeDeflection) {
  // A soft cantilever bent far (tip deflection ≈ 40% of its length) in one static solve.
  const xpbd::TetMesh mesh = xpbd::make_box_tet_mesh(Vec3(0.1, 0.02, 0.02), 10, 2, 2);
  xpbd::Model model;
  model.particles = xpbd::make_particles(mesh, 1000.0);
  xpbd::add_neo_hookean_tets(model, mesh, xpbd::lame_from_young_poisson(3e3, 0.3));
  xpbd::pin_particles(model, xpbd::vertices_at_min_x(mesh.V));
  ImplicitSolver solver(model, {.newton = {.tolerance = 1e-10}});
  const NewtonReport report = solver.solve_static();
  EXPECT_TRUE(report.converged);
  EXPECT_LT(report.iterations, 40);
  EXPECT_GT(mesh.V.col(2).maxCoeff() - model.particles.x.col(2).minCoeff(), 0.02);
}

TEST(SparseHessian, AssemblyDropsPinnedRowsAndColumns) {
  const xpbd::Model model = block(1);
  const auto form = make_constraint_form<NeoHookeanKernel>("neo-hookean", model.neo_hookean);
  std::vector<bool> fixed(model.particles.size(), false);
  fixed[0] = fixed[5] = true;
  const DofMap pinned(fixed), all(std::vector<bool>(model.particles.size(), false));
  SparseHessian H_pinned(pinned, {form->stencils()}), H_all(all, {form->stencils()});
  Positions x = model.particles.x;
  x(3, 1) += 1e-3;
  form->add_hessian(x, 2.0, false, H_pinned);
  form->add_hessian(x, 2.0, false, H_all);
  const Eigen::MatrixXd full(H_all.matrix());
  std::vector<int> keep;
  for (int i = 0; i < model.particles.size(); ++i)
    if (!fixed[i])
      for (int c = 0; c < 3; ++c) keep.push_back(3 * i + c);
  const Eigen::MatrixXd expected = full(keep, keep);
  EXPECT_EQ(Eigen::MatrixXd(H_pinned.matrix()), expected);
}

TEST(ImplicitSolver, RejectsModelsItCannotSolve) {
  xpbd::Model with_box = block(1);
  xpbd::Collider box;
  box.shape = xpbd::ColliderShape::kBox;
  box.half_extents = xpbd::Vec3::Ones();
  with_box.colliders.push_back(box);
  EXPECT_THROW(ImplicitSolver(with_box, {}), std::invalid_argument);  // the barrier knows planes and spheres
  xpbd::Model below = block(1);
  below.ground = xpbd::GroundPlane{};
  below.particles.x.col(2).array() -= 0.5;
  EXPECT_THROW(ImplicitSolver(below, {}).step(), xpbd::SimulationError);
  xpbd::Model bad_sizes = block(1);
  bad_sizes.particles.v.resize(2, 3);
  EXPECT_THROW(ImplicitSolver(bad_sizes, {}), std::invalid_argument);
  xpbd::Model model = block(1);
  EXPECT_THROW(ImplicitSolver(model, {.time_step = 0.0, .newton = {}}), std::invalid_argument);
  EXPECT_THROW(ImplicitSolver(model, {.newton = {.tolerance = -1.0}}), std::invalid_argument);
}

TEST(ImplicitSolver, BarrierCarriesTheWeightOfABlockOnTheGround) {
  // A 1 cm block set d̂/2 above the ground: the static solve ends with every particle above
  // it, the lowest within d̂, and the contact force equal to the weight.
  xpbd::Model model = block(2);
  const BarrierSettings barrier;
  model.particles.x.col(2).array() += 0.5 * barrier.activation_distance - model.particles.x.col(2).minCoeff();
  model.ground = xpbd::GroundPlane{};
  ImplicitSolver solver(model, {.time_step = 1e-3, .newton = {.tolerance = 1e-10}}, barrier);
  ASSERT_TRUE(solver.solve_static().converged);
  const double weight = (1.0 / model.particles.w.array()).sum() * 9.81;
  const xpbd::Vec3 force = solver.contact()->contact_force(model.particles.x, 0);
  EXPECT_NEAR(force.z(), weight, 1e-6 * weight);
  EXPECT_LT(force.head<2>().norm(), 1e-6 * weight);
  EXPECT_GT(model.particles.x.col(2).minCoeff(), 0.0);
  EXPECT_LT(model.particles.x.col(2).minCoeff(), barrier.activation_distance);
}

TEST(ImplicitSolver, CollisionSpheresCarryTheUpperOfTwoStackedGrains) {
  // Two soft grain-sized bodies (xpbd grain fixture, E = 50 kPa), one on the other, the same
  // contact geometry as XPBD's contact solver: the lower grain's bottom face is held, the
  // upper one rests on it. A sphere resting on a sphere without friction is unstable (the
  // upper grain slides off), so four weak springs (k = 1 N/m, five times the contacts'
  // negative lateral stiffness F/2r) hold the upper grain's top corners. At rest its forces
  // balance: the spheres' barrier and the springs carry its weight, the barrier most of it,
  // and no two spheres overlap.
  const BarrierSettings barrier{.activation_distance = 1e-5, .stiffness = 1e3};
  xpbd::Model model;
  xpbd::test_support::add_grain(model, xpbd::BodyKind::kSoft, xpbd::Vec3::Zero());
  const int upper = xpbd::test_support::add_grain(
      model, xpbd::BodyKind::kSoft, xpbd::Vec3(0.0, 0.0, xpbd::test_support::kGrainThickness + 0.5 * barrier.activation_distance));
  const xpbd::Body& top = model.bodies[upper];
  std::vector<int> bottom;
  for (int i = 0; i < model.bodies[0].particle_count; ++i)
    if (model.particles.x(i, 2) == 0.0) bottom.push_back(i);
  xpbd::pin_particles(model, bottom);
  const double top_z = model.particles.x.middleRows(top.first_particle, top.particle_count).col(2).maxCoeff();
  for (int i = top.first_particle; i < top.first_particle + top.particle_count; ++i) {
    const xpbd::Vec3 x = model.particles.x.row(i).transpose();
    const bool corner = x.z() == top_z && (x.x() == 0.0 || std::abs(x.x() - xpbd::test_support::kGrainLength) < 1e-12) &&
                        (x.y() == 0.0 || std::abs(x.y() - xpbd::test_support::kGrainWidth) < 1e-12);
    if (corner) model.attachments.push_back({i, x, 1.0});  // α = 1 m/N
  }
  ASSERT_EQ(model.attachments.size(), 4u);
  ImplicitSolver solver(model, {.time_step = 1e-3, .newton = {.tolerance = 1e-10, .max_iterations = 500}}, barrier);
  ASSERT_NE(solver.sphere_pairs(), nullptr);
  EXPECT_EQ(solver.sphere_planes(), nullptr);  // no colliders
  ASSERT_TRUE(solver.solve_static().converged);
  const double weight = 9.81 * (1.0 / model.particles.w.segment(top.first_particle, top.particle_count).array()).sum();
  xpbd::Vec3 springs = xpbd::Vec3::Zero();
  for (const xpbd::Attachment& a : model.attachments)
    springs += (a.target - model.particles.x.row(a.particle).transpose()) / a.compliance;
  const xpbd::Vec3 on_upper = solver.sphere_pairs()->force_on_body(model.particles.x, upper);
  EXPECT_NEAR(on_upper.z() + springs.z(), weight, 1e-6 * weight);
  EXPECT_LT((on_upper.head<2>() + springs.head<2>()).norm(), 1e-6 * weight);
  EXPECT_GT(on_upper.z(), 0.9 * weight);  // the springs carry little of it
  EXPECT_NEAR((on_upper + solver.sphere_pairs()->force_on_body(model.particles.x, 0)).norm(), 0.0, 1e-9 * weight);
  EXPECT_TRUE(std::isfinite(solver.sphere_pairs()->value(model.particles.x)));  // no overlap
}

TEST(ImplicitSolver, BlockDroppedOnASphereColliderNeverEntersIt) {
  // A 1 cm block falls at 2 m/s onto a sphere collider of radius 2 cm: 2 mm a step at
  // h = 1 ms, twenty times d̂. Every particle stays outside at every step.
  xpbd::Model model = block(2);
  const double radius = 0.02;
  const xpbd::Vec3 centre(0.005, 0.004, -radius - 1e-3);
  xpbd::Collider sphere;
  sphere.shape = xpbd::ColliderShape::kSphere;
  sphere.radius = radius;
  sphere.motion[0].translation = centre;
  model.colliders.push_back(sphere);
  model.particles.v.col(2).setConstant(-2.0);
  ImplicitSolver solver(model, {.time_step = 1e-3, .newton = {.tolerance = 1e-8}});
  double closest = 1.0;
  for (int step = 0; step < 60; ++step) {
    solver.step();
    const double gap =
        ((model.particles.x.rowwise() - centre.transpose()).rowwise().norm().array() - radius).minCoeff();
    ASSERT_GT(gap, 0.0) << "step " << step;
    closest = std::min(closest, gap);
  }
  EXPECT_LT(closest, BarrierSettings{}.activation_distance);  // it did touch
  EXPECT_GT(model.particles.v.col(2).mean(), -2.0);            // and was stopped or deflected
}

}  // namespace
}  // namespace rice::fem
