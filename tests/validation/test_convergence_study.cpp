// The convergence study's claims on a small grid: XPBD approaches the reference as substeps
// and iterations grow; from one state, more iterations bring its step closer to Newton's until
// it reaches its own fixed point, which stays off Newton's step (the primal-residual gap): its
// constraint residual vanishes there while its primal residual does not. Every reference solve
// converges and each panel has a Pareto front. Vertex block descent, converged, is the
// reference's step.
#include <gtest/gtest.h>

#include <algorithm>

#include "experiments/studies/convergence_study.hpp"

namespace rice::experiments {
namespace {

const ConvergenceRun& find(const std::vector<ConvergenceRun>& runs, const std::string& scene, double tau,
                           int substeps, int iterations) {
  const auto it = std::find_if(runs.begin(), runs.end(), [&](const ConvergenceRun& r) {
    return r.scene == scene && r.method == "xpbd" && r.rayleigh_time == tau && r.substeps == substeps &&
           r.iterations == iterations;
  });
  if (it == runs.end()) throw std::runtime_error("run not found");
  return *it;
}

TEST(ConvergenceStudy, XpbdApproachesTheReferenceWithMoreWork) {
  ConvergenceSettings s;
  s.duration = 3.0 / 60.0;
  s.substeps = {16, 64};
  s.iterations = {1, 5, 50};
  s.resolutions = {1};
  s.grid_resolution = 1;
  s.sample_every = 1;
  const std::vector<ConvergenceRun> runs = run_convergence_study(s);
  for (const ConvergenceRun& r : runs) {
    EXPECT_FALSE(r.failed) << r.scene << " " << r.method << " N " << r.substeps << " K " << r.iterations;
  }
  for (const std::string scene : {"hanging-cantilever", "twisted-bar"}) {
    for (const double tau : {0.0, s.rayleigh_time}) {
      SCOPED_TRACE(scene + " tau " + std::to_string(tau));
      const ConvergenceRun& cheap = find(runs, scene, tau, 16, 5);
      const ConvergenceRun& dear = find(runs, scene, tau, 64, 50);
      EXPECT_LT(dear.trajectory_error, cheap.trajectory_error);
      EXPECT_LT(dear.trajectory_error, 1e-3);
      const ConvergenceRun& one = find(runs, scene, tau, 64, 1);
      const ConvergenceRun& few = find(runs, scene, tau, 64, 5);
      EXPECT_LT(dear.step_distance, one.step_distance);
      EXPECT_NEAR(dear.step_distance, few.step_distance, 0.01 * few.step_distance) << "fixed point by K = 5";
      EXPECT_GT(dear.step_distance, 1e-8) << "XPBD's fixed point is not Newton's step";
      EXPECT_LT(dear.constraint_residual, 0.01 * one.constraint_residual);
      EXPECT_GT(dear.primal_residual, 0.1 * one.primal_residual);
      const auto on_front = std::count_if(runs.begin(), runs.end(), [&](const ConvergenceRun& r) {
        return r.scene == scene && r.rayleigh_time == tau && r.method == "xpbd" && r.pareto;
      });
      EXPECT_GE(on_front, 1);
    }
  }
  EXPECT_TRUE(std::any_of(runs.begin(), runs.end(), [](const ConvergenceRun& r) { return r.method == "pbd"; }));
  // Vertex block descent minimises the reference's own step potential: converged, its step
  // is Newton's (XPBD's stays off it, above), for every kind of damping.
  for (const std::string damping : {"none", "constraint", "strain-rate"}) {
    for (const std::string scene : {"hanging-cantilever", "twisted-bar"}) {
      const auto vbd = std::find_if(runs.begin(), runs.end(), [&](const ConvergenceRun& r) {
        return r.scene == scene && r.method == "vbd" && r.damping == damping && r.substeps == 16 && r.iterations == 50;
      });
      ASSERT_NE(vbd, runs.end()) << scene << " " << damping;
      EXPECT_LT(vbd->step_distance, 1e-9) << scene << " " << damping;
      EXPECT_LT(vbd->trajectory_error, 1e-6) << scene << " " << damping;
    }
  }
}

TEST(ConvergenceStudy, RejectsAGridResolutionOutsideTheResolutions) {
  ConvergenceSettings s = ConvergenceSettings::quick();
  s.grid_resolution = 3;
  EXPECT_THROW(run_convergence_study(s), std::invalid_argument);
}

}  // namespace
}  // namespace rice::experiments
