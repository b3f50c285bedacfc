// XPBD's primal-residual correction against the reference (xpbd/solver.hpp,
// SolverSettings::primal_correction): one step from a bent cantilever state. Plain XPBD reaches
// its fixed point in a few sweeps but stays off Newton's solution with g ≠ 0; with the
// correction its fixed point is backward Euler itself, to round-off.
#include <gtest/gtest.h>

#include "experiments/studies/convergence_scenes.hpp"
#include "fem_reference/implicit_solver.hpp"
#include "fem_reference/trajectory_error.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {
namespace {

TEST(PrimalCorrection, ConvergedXpbdStepBecomesTheNewtonStep) {
  const BarSettings bar;
  const double h = 1.0 / 60.0 / 64.0;
  xpbd::Model model = make_scene(ConvergenceScene::kHangingCantilever, BodyModel::kNeoHookean, bar, 1, Damping::kNone, 0.0);
  fem::ImplicitSolver reference(model, {.time_step = h, .newton = {.tolerance = 1e-12}});
  for (int s = 0; s < 200; ++s) reference.step();  // bend it
  const xpbd::Model start = model;
  reference.step();
  const xpbd::Positions newton = model.particles.x;

  double distance[2], primal[2];
  for (const bool correct : {false, true}) {
    xpbd::Model m = start;
    xpbd::Solver solver(m, {.time_step = h, .iterations = 100, .execution = xpbd::Execution::kSerial,
                            .primal_correction = correct, .diagnostics = true});
    solver.step();
    distance[correct] = fem::rms_distance(m.particles.x, newton) / bar.length;
    primal[correct] = solver.diagnostics().primal_residual;
    EXPECT_LT(solver.diagnostics().constraint_residual, 1e-12) << "converged, correction " << correct;
  }
  EXPECT_GT(distance[0], 1e-7) << "plain XPBD stops short of Newton";
  EXPECT_LT(distance[1], 1e-12) << "corrected XPBD reaches it";
  EXPECT_LT(primal[1], 1e-6 * primal[0]);
}

}  // namespace
}  // namespace rice::experiments
