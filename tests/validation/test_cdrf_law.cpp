// The σ0 law stored in the water-content model (grains/water_content.cpp) against a fresh fit
// to the random-walk reference (experiments/studies/cdrf_study.hpp), at a water content between the
// study's points: the stored constants are what the study produces, not numbers typed in.
#include <gtest/gtest.h>

#include "experiments/studies/cdrf_study.hpp"
#include "grains/water_content.hpp"

namespace rice::experiments {
namespace {

TEST(CdrfLaw, StoredSigma0MatchesAFreshFitToTheRandomWalk) {
  CdrfStudySettings settings;
  settings.photons = 40'000;  // a fifth of the study's: σ0 moves by ~2% between seeds
  settings.seed = 11;         // not the study's seed
  const double absorption = 21.0;
  const WaterContentFit fresh = fit_water_content(absorption, settings);
  EXPECT_FALSE(fresh.fit.at_bound);
  EXPECT_NEAR(fresh.fit.sigma0 / grains::WaterContentModel::scattering_sigma0(absorption), 1.0, 0.08);
  // The fit's quality as the study measured it: within 15% RMS of the mean exitance.
  EXPECT_LT(fresh.fit.rms, 0.15 * fresh.mean_exitance);
}

}  // namespace
}  // namespace rice::experiments
