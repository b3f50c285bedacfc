// What a pile looks like from above (experiments/pile/pile_measures.hpp): the footprint radius
// holds its fraction of the centres, and touching grains form groups.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "experiments/pile/pile_measures.hpp"
#include "tests/xpbd/grain_fixtures.hpp"

namespace rice::experiments {
namespace {

TEST(PileMeasures, FootprintRadiusHoldsTheFractionOfCentresAboutTheirMean) {
  // Ten centres on a circle of 2 cm about (1, 1), one at its middle, heights anything.
  std::vector<xpbd::Vec3> centres{xpbd::Vec3(1.0, 1.0, 0.3)};
  for (int k = 0; k < 10; ++k) {
    const double t = 2.0 * M_PI * k / 10.0;
    centres.emplace_back(1.0 + 0.02 * std::cos(t), 1.0 + 0.02 * std::sin(t), 0.01 * k);
  }
  EXPECT_NEAR(footprint_radius(centres, 0.9), 0.02, 1e-12);
  EXPECT_NEAR(footprint_radius(centres, 1.0 / 11.0), 0.0, 1e-12);  // the middle one alone
  EXPECT_EQ(footprint_radius({}), 0.0);
}

// The rice cooker's section was cut half way to its highest grain, one the paddle lifted 11 cm
// up over a 1.6 cm layer, and showed no grain.
TEST(PileMeasures, APilesTopIsNotSetByAFewGrainsLiftedAboveIt) {
  std::vector<xpbd::Vec3> centres;
  for (int k = 0; k < 100; ++k) centres.emplace_back(0.0, 0.0, 0.016 * k / 99.0);  // a layer 1.6 cm deep
  for (int k = 0; k < 3; ++k) centres.emplace_back(0.0, 0.0, 0.11);               // three on the paddle
  EXPECT_LT(pile_top(centres), 0.016);
  EXPECT_GT(pile_top(centres), 0.014);
  EXPECT_EQ(pile_top(centres, 1.0), 0.11);
  EXPECT_TRUE(std::isnan(pile_top({})));
}

TEST(PileMeasures, ClustersAreTheGroupsOfGrainsWhoseSpheresTouch) {
  // Three grain-sized bodies in a row 50 µm apart and a fourth far away: two groups at a gap
  // of 0.1 mm, four at 10 µm.
  xpbd::Model model;
  for (int g = 0; g < 3; ++g)
    xpbd::test_support::add_grain(model, xpbd::BodyKind::kRigid, xpbd::Vec3(0.0, g * (xpbd::test_support::kGrainWidth + 5e-5), 0.0));
  xpbd::test_support::add_grain(model, xpbd::BodyKind::kSoft, xpbd::Vec3(0.1, 0.0, 0.0));
  EXPECT_EQ(count_clusters(model, 1e-4), 2);
  EXPECT_EQ(count_clusters(model, 1e-5), 4);
}

}  // namespace
}  // namespace rice::experiments
