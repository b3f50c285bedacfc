// The XPBD paper's claim, checked on a small cantilever: XPBD's rest deflection does not
// depend on the iteration count while PBD's does.
#include <gtest/gtest.h>

#include "experiments/studies/xpbd_stiffness_study.hpp"

namespace rice::experiments {
namespace {

TEST(StiffnessStudy, XpbdRestDeflectionIsIndependentOfIterationsAndPbdIsNot) {
  StiffnessStudySettings settings;
  settings.iterations = {10, 20};
  settings.cells_along = 5;
  settings.substeps = 25;
  const std::vector<StiffnessRun> runs = run_stiffness_study(settings);
  for (const StiffnessRun& r : runs) {
    EXPECT_TRUE(r.reached_rest) << r.method << " K=" << r.iterations;
    EXPECT_GT(r.tip_deflection, 0.0) << r.method << " K=" << r.iterations;
  }
  EXPECT_LT(relative_spread(runs, "xpbd-neo-hookean"), 1e-3);
  EXPECT_LT(relative_spread(runs, "xpbd-springs"), 1e-3);
  EXPECT_GT(relative_spread(runs, "pbd-springs"), 0.5);
}

}  // namespace
}  // namespace rice::experiments
