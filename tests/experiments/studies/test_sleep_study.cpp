// The sleep study's measure of two settled piles (experiments/studies/sleep_study.hpp): the
// 1-Wasserstein distance of known samples, equal and unequal in size, and its refusals.
#include <gtest/gtest.h>

#include <stdexcept>

#include "experiments/studies/sleep_study.hpp"

namespace rice::experiments {
namespace {

TEST(Wasserstein1, IsZeroForOneSampleShuffledAndTheShiftForAShiftedOne) {
  const std::vector<double> a{0.3, -1.0, 2.5, 0.0};
  EXPECT_EQ(wasserstein_1(a, {2.5, 0.0, 0.3, -1.0}), 0.0);
  EXPECT_NEAR(wasserstein_1(a, {2.75, 0.25, 0.55, -0.75}), 0.25, 1e-15);
  // Matched by rank, not by index: {0, 1} against {1, 0} is 0, where grain by grain it is 1.
  EXPECT_EQ(wasserstein_1({0.0, 1.0}, {1.0, 0.0}), 0.0);
}

TEST(Wasserstein1, ComparesQuantilesOfSamplesOfDifferentSizes) {
  EXPECT_EQ(wasserstein_1({0.0, 1.0}, {0.0, 0.0, 1.0, 1.0}), 0.0);  // the same distribution
  EXPECT_EQ(wasserstein_1({0.0}, {1.0, 3.0}), 2.0);                  // ½ |0 − 1| + ½ |0 − 3|
  EXPECT_THROW(wasserstein_1({}, {1.0}), std::invalid_argument);
}

TEST(SleepStudy, RefusesSettingsOutOfRange) {
  SleepStudySettings s;
  s.scene = RICE_SCENES_DIR "/rice_cooker.toml";
  EXPECT_NO_THROW(validate(s));
  s.sleep_frames = {0};
  EXPECT_THROW(validate(s), std::invalid_argument);
  s.sleep_frames = {};
  s.sleep_speeds = {};
  EXPECT_THROW(validate(s), std::invalid_argument);
  s.sleep_speeds = {1.5};
  EXPECT_THROW(validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace rice::experiments
