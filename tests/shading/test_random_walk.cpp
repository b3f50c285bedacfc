// Random-walk subsurface scattering (shading/random_walk.hpp), the Fresnel interface it
// uses, and the σ0 fit (shading/sigma0_fit.hpp): conservation, closed forms, determinism.
#include "shading/random_walk.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "shading/cdrf.hpp"
#include "shading/fresnel.hpp"
#include "shading/sigma0_fit.hpp"

namespace rice::shading {
namespace {


TEST(Fresnel, NormalIncidenceGrazingAndTotalInternalReflection) {
  const double eta = 1.45;
  EXPECT_NEAR(fresnel_reflectance(1.0, eta), std::pow((eta - 1) / (eta + 1), 2), 1e-15);
  EXPECT_NEAR(fresnel_reflectance(1e-9, eta), 1.0, 1e-6);
  const double critical = std::sqrt(1.0 - 1.0 / (eta * eta));  // cos of the critical angle inside
  EXPECT_EQ(fresnel_reflectance(critical - 1e-6, 1.0 / eta), 1.0);
  EXPECT_LT(fresnel_reflectance(critical + 1e-3, 1.0 / eta), 1.0);
  // Reciprocity: the same interface seen from both sides reflects the same fraction.
  for (double cos_i : {0.2, 0.5, 0.9}) {
    const double cos_t = std::sqrt(1.0 - (1.0 - cos_i * cos_i) / (eta * eta));
    EXPECT_NEAR(fresnel_reflectance(cos_i, eta), fresnel_reflectance(cos_t, 1.0 / eta), 1e-14);
  }
}

TEST(Fresnel, RefractionObeysSnell) {
  const Eigen::Vector3d n(0, 0, 1);
  const Eigen::Vector3d d = Eigen::Vector3d(0.6, 0, -0.8);
  const Eigen::Vector3d t = refract(d, n, 1.5);
  EXPECT_NEAR(t.norm(), 1.0, 1e-14);
  EXPECT_NEAR(t.x(), 0.6 / 1.5, 1e-14);  // sin θ_t = sin θ_i / η, same plane
  EXPECT_LT(t.z(), 0.0);
}

TEST(RandomWalk, WithoutAbsorptionOrInterfaceEveryPhotonComesOut) {
  const Medium clear_boundary{2000.0, 0.0, 0.5, 1.0};
  const auto p = sphere_exitance(clear_boundary, 1e-3, {.photons = 20000});
  EXPECT_NEAR(p.entered, 1.0, 1e-12);
  EXPECT_NEAR(p.escaped + p.ballistic, 1.0, 1e-12);
  // Exitance over the sphere, Σ M_k 2π r² Δcos θ_k, over the beam's flux E π r², is the escaped fraction.
  double total = 0.0;
  for (std::size_t k = 0; k < p.theta.size(); ++k) {
    const double lo = std::numbers::pi * k / p.theta.size(), hi = std::numbers::pi * (k + 1) / p.theta.size();
    total += p.exitance[k] * 2.0 * (std::cos(lo) - std::cos(hi));
  }
  EXPECT_NEAR(total, p.escaped, 1e-12);
}

// A purely absorbing, index-matched sphere: what comes through is Beer–Lambert along each
// chord, averaged over the beam: (2/R²) ∫_0^R e^{−2σ_a u} u du = (1 − e^{−2aR}(1 + 2aR)) / (2 a² R²).
TEST(RandomWalk, AbsorbingSphereTransmitsBeerLambertOverItsChords) {
  const double radius = 1e-3, sigma_a = 800.0;
  const auto p = sphere_exitance({0.0, sigma_a, 0.0, 1.0}, radius, {.photons = 200000});
  const double x = 2 * sigma_a * radius;
  const double expected = (1.0 - std::exp(-x) * (1.0 + x)) / (0.5 * x * x);
  EXPECT_NEAR(p.ballistic, expected, 3e-3);  // binomial spread of 2e5 photons: ~1e-3
  EXPECT_EQ(p.escaped, 0.0);
}

TEST(RandomWalk, FresnelAtEntryMatchesTheBeamAveragedReflectance) {
  const double eta = 1.45;
  const auto p = sphere_exitance({1000.0, 10.0, 0.0, eta}, 1e-3, {.photons = 200000});
  // Beam-averaged transmittance: ∫_0^1 (1 − F(μ)) 2μ dμ (uniform over the silhouette disk).
  double expected = 0.0;
  const int n = 100000;
  for (int k = 0; k < n; ++k) {
    const double mu = (k + 0.5) / n;
    expected += (1.0 - fresnel_reflectance(mu, eta)) * 2 * mu / n;
  }
  EXPECT_NEAR(p.entered, expected, 2e-3);
}

TEST(RandomWalk, SameSeedSameProfileOnAnyThreadCount) {
  const Medium medium{3000.0, 10.0, 0.3, 1.4};
  const RandomWalkOptions options{.photons = 30000, .seed = 5, .batch = 1000};
  ExitanceProfile one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = sphere_exitance(medium, 1e-3, options);
  }
  const auto many = sphere_exitance(medium, 1e-3, options);
  EXPECT_EQ(one.exitance, many.exitance);
  EXPECT_EQ(one.escaped, many.escaped);
}

TEST(RandomWalk, RefusesBadInput) {
  EXPECT_THROW(sphere_exitance({1000, 0, 0, 1.4}, 0.0), std::invalid_argument);
  EXPECT_THROW(sphere_exitance({0, 0, 0, 1.4}, 1e-3), std::invalid_argument);
  EXPECT_THROW(sphere_exitance({1000, 0, 1.0, 1.4}, 1e-3), std::invalid_argument);
  EXPECT_THROW(sphere_exitance({1000, 0, 0, 1.4}, 1e-3, {.photons = 0}), std::invalid_argument);
}

TEST(Sigma0Fit, RecoversAKnownWidthFromExactData) {
  std::vector<ExitanceSample> samples;
  for (double radius : {0.5e-3, 1e-3, 2e-3}) {
    for (int k = 0; k < 24; ++k) {
      const double theta = std::numbers::pi * (k + 0.5) / 24;
      samples.push_back({theta, 1.0 / radius, 0.8 * cdrf_integral(std::cos(theta), 0.4e-3 / radius)});
    }
  }
  const auto fit = fit_sigma0(samples, 1e-6, 1e-1);
  EXPECT_NEAR(fit.sigma0, 0.4e-3, 1e-9);
  EXPECT_NEAR(fit.amplitude, 0.8, 1e-6);
  EXPECT_LT(fit.rms, 1e-7);
  EXPECT_FALSE(fit.at_bound);
  EXPECT_THROW(fit_sigma0(samples, 1e-3, 1e-4), std::invalid_argument);
}

// The CDRF's premise, σ = σ0 κ: the width fitted on its own to spheres of radius 1 mm and
// 4 mm is nearly the same σ0, although σ itself differs fourfold.
TEST(Sigma0Fit, WidthFittedToTheRandomWalkScalesWithCurvature) {
  const Medium medium{4000.0, 10.0, 0.0, 1.45};
  double sigma0[2];
  int i = 0;
  for (double radius : {1e-3, 4e-3}) {
    const auto p = sphere_exitance(medium, radius, {.photons = 40000, .bins = 24});
    std::vector<ExitanceSample> samples;
    for (std::size_t k = 0; k < p.theta.size(); ++k) samples.push_back({p.theta[k], 1.0 / radius, p.exitance[k]});
    const auto fit = fit_sigma0(samples, 1e-6, 1e-1);
    EXPECT_FALSE(fit.at_bound);
    EXPECT_LT(fit.rms, 0.05);
    sigma0[i++] = fit.sigma0;
  }
  EXPECT_NEAR(sigma0[1] / sigma0[0], 1.0, 0.5) << sigma0[0] << " " << sigma0[1];
}

}  // namespace
}  // namespace rice::shading
