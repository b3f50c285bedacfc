// Vertex block descent (xpbd/vertex_block_descent.hpp) against the reference solver: both
// minimise the same backward-Euler potential, so a converged VBD step is the Newton step, with
// and without either kind of damping; and XPBD's strain-rate damping pass converges to it
// as the substep shrinks.
#include <gtest/gtest.h>

#include "fem_reference/implicit_solver.hpp"
#include "fem_reference/trajectory_error.hpp"
#include "xpbd/solver.hpp"

namespace rice {
namespace {

using xpbd::Vec3;

/// The convergence study's bar (0.1 m × 0.02 m × 0.02 m, E = 100 kPa, ν = 0.3), clamped at
/// x = 0, under gravity, with the given damping times.
xpbd::Model bar(double constraint_time, double strain_rate_time) {
  const xpbd::TetMesh mesh = xpbd::make_box_tet_mesh(Vec3(0.1, 0.02, 0.02), 5, 1, 1);
  xpbd::Model model;
  model.particles = xpbd::make_particles(mesh, 1000.0);
  xpbd::add_neo_hookean_tets(model, mesh, xpbd::lame_from_young_poisson(1e5, 0.3), constraint_time,
                             strain_rate_time);
  xpbd::pin_particles(model, xpbd::vertices_at_min_x(mesh.V));
  return model;
}

/// The bar after 0.1 s of sagging from rest (reference, h = 1/600 s): bent and moving.
xpbd::Model moving_bar(double constraint_time, double strain_rate_time) {
  xpbd::Model model = bar(constraint_time, strain_rate_time);
  fem::ImplicitSolver reference(model, {.time_step = 1.0 / 600.0, .newton = {.tolerance = 1e-10}});
  for (int n = 0; n < 60; ++n) reference.step();
  return model;
}

struct Damping {
  const char* name;
  double constraint_time, strain_rate_time;
};

class VertexBlockDescentStep : public ::testing::TestWithParam<Damping> {};

TEST_P(VertexBlockDescentStep, ConvergedStepIsTheReferenceStep) {
  const Damping d = GetParam();
  const double h = 1.0 / 60.0;  // ten times the bar's wave-crossing time
  xpbd::Model start = moving_bar(d.constraint_time, d.strain_rate_time);
  xpbd::Model vbd = start, newton = start;
  fem::ImplicitSolver(newton, {.time_step = h, .newton = {.tolerance = 1e-12}}).step();
  xpbd::Solver(vbd, {.time_step = h, .iterations = 5000, .method = xpbd::Method::kVbd,
                     .execution = xpbd::Execution::kSerial})
      .step();
  const double moved = fem::rms_distance(newton.particles.x, start.particles.x);
  EXPECT_LT(fem::rms_distance(vbd.particles.x, newton.particles.x), 1e-8 * moved);
  EXPECT_LT(fem::rms_distance(vbd.particles.v, newton.particles.v), 1e-8 * moved / h);
}

INSTANTIATE_TEST_SUITE_P(Damping, VertexBlockDescentStep,
                         ::testing::Values(Damping{"none", 0.0, 0.0}, Damping{"constraint", 2e-3, 0.0},
                                           Damping{"strain_rate", 0.0, 5e-3}, Damping{"both", 2e-3, 5e-3}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace rice
