// The frame-cost study's equal-error sample count and time (experiments/studies/frame_cost_study.hpp):
// exact on a power law inside and past the sweep, and refused for mismatched curves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "experiments/studies/frame_cost_study.hpp"

namespace rice::experiments {
namespace {

TEST(EqualErrorCost, IsExactOnAPowerLawInsideAndPastTheSweep) {
  const std::vector<double> spp{4, 8, 16, 32, 64};
  std::vector<double> error;
  for (const double n : spp) error.push_back(0.5 / std::pow(n, 0.75));  // Sobol-like: faster than 1/sqrt(n)
  const double n_star = 23.0;
  EXPECT_NEAR(equal_error_cost(spp, error, 0.5 / std::pow(n_star, 0.75)), n_star, 1e-9);
  EXPECT_NEAR(equal_error_cost(spp, error, error[2]), 16.0, 1e-9);
  EXPECT_EQ(equal_error_cost(spp, error, 1.0), 4.0);  // below the target from the first count
  // Past the sweep: along the last segment, exact on the power law too.
  EXPECT_NEAR(equal_error_cost(spp, error, 0.5 / std::pow(100.0, 0.75)), 100.0, 1e-9);
  EXPECT_EQ(equal_error_cost(spp, {0.3, 0.2, 0.2, 0.2, 0.2}, 0.1), std::numeric_limits<double>::infinity());
  EXPECT_THROW(equal_error_cost(spp, {0.1, 0.05}, 0.07), std::invalid_argument);
}

TEST(FrameCostStudy, RefusesAWindowOutsideTheFrameAndUnsortedCountsOrErrors) {
  FrameCostStudySettings s;
  s.run = RICE_SCENES_DIR;  // a folder; validate reads nothing else
  EXPECT_NO_THROW(validate(s));
  s.window_width = s.width + 1;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s.window_width = 16;
  s.sobol_spp = {8, 4};
  EXPECT_THROW(validate(s), std::invalid_argument);
  s.sobol_spp = {4, 8};
  s.adaptive_errors = {0.05, 0.1};
  EXPECT_THROW(validate(s), std::invalid_argument);
  s.adaptive_errors = {0.1, 0.05};
  s.adaptive_max_spp = s.adaptive_min_spp;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s.adaptive_max_spp = 64;
  EXPECT_NO_THROW(validate(s));
  s.integrator = RenderIntegrator::kPath;
  EXPECT_THROW(validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace rice::experiments
