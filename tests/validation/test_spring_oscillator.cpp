// Validation against an analytic result: an XPBD spring–mass oscillator reproduces the period
// and decay rate of m ẍ + β ẋ + k x = 0, with the backward-Euler damping error h ω0²/2 that
// vanishes at first order in h.
#include <gtest/gtest.h>

#include <cmath>

#include "experiments/studies/oscillator_study.hpp"

namespace rice::experiments {
namespace {

TEST(SpringOscillator, PeriodAndDecayMatchTheAnalyticOscillator) {
  const OscillatorSettings settings;
  const double omega0 = std::sqrt(settings.stiffness / settings.mass);
  for (const double damping : {0.0, 0.5, 2.0}) {
    const OscillationMeasurement exact = analytic_oscillator(settings, damping);
    for (const int substeps : {16, 64}) {
      const double h = settings.frame / substeps;
      const OscillationMeasurement m = simulate_oscillator(settings, substeps, damping);
      EXPECT_NEAR(m.period, exact.period, 1.5e-3 * exact.period) << "beta " << damping << ", N " << substeps;
      // Backward Euler adds decay h ω0² / 2; the rest must be the physical decay.
      EXPECT_NEAR(m.decay_rate, exact.decay_rate + 0.5 * h * omega0 * omega0, 0.02 * exact.decay_rate + 1e-3)
          << "beta " << damping << ", N " << substeps;
    }
  }
}

TEST(SpringOscillator, ReferenceSolverMatchesTheAnalyticOscillatorAndXpbd) {
  // The reference's Rayleigh potential β/(2h)(C − Cⁿ)² equals XPBD's damping for a spring
  // moving along its axis, and one XPBD iteration solves a single linear constraint exactly:
  // both are the same backward-Euler map here, so they agree to round-off.
  const OscillatorSettings settings;
  const double omega0 = std::sqrt(settings.stiffness / settings.mass);
  for (const double damping : {0.0, 0.5}) {
    const OscillationMeasurement exact = analytic_oscillator(settings, damping);
    for (const int substeps : {16, 64}) {
      const double h = settings.frame / substeps;
      std::vector<double> xpbd, reference;
      simulate_oscillator(settings, substeps, damping, Integrator::kXpbd, &xpbd);
      const OscillationMeasurement m =
          simulate_oscillator(settings, substeps, damping, Integrator::kReference, &reference);
      EXPECT_NEAR(m.period, exact.period, 1.5e-3 * exact.period) << "beta " << damping << ", N " << substeps;
      EXPECT_NEAR(m.decay_rate, exact.decay_rate + 0.5 * h * omega0 * omega0, 0.02 * exact.decay_rate + 1e-3)
          << "beta " << damping << ", N " << substeps;
      ASSERT_EQ(xpbd.size(), reference.size());
      double difference = 0.0;
      for (size_t k = 0; k < xpbd.size(); ++k) difference = std::max(difference, std::abs(xpbd[k] - reference[k]));
      EXPECT_LT(difference, 1e-9 * settings.amplitude) << "beta " << damping << ", N " << substeps;
    }
  }
}

TEST(SpringOscillator, DecayErrorIsFirstOrderInTheSubstep) {
  const OscillatorSettings settings;
  const OscillationMeasurement exact = analytic_oscillator(settings, settings.damping);
  const double e8 = simulate_oscillator(settings, 8, settings.damping).decay_rate - exact.decay_rate;
  const double e16 = simulate_oscillator(settings, 16, settings.damping).decay_rate - exact.decay_rate;
  EXPECT_NEAR(e8 / e16, 2.0, 0.1);
}

TEST(SpringOscillator, MeasurementRecoversAKnownSignal) {
  std::vector<double> t, x;
  for (int i = 0; i < 4000; ++i) {
    t.push_back(i * 1e-3);
    x.push_back(std::exp(-0.7 * t.back()) * std::cos(2.0 * M_PI * t.back() / 0.5));
  }
  const OscillationMeasurement m = measure_oscillation(t, x);
  EXPECT_NEAR(m.period, 0.5, 1e-5);
  EXPECT_NEAR(m.decay_rate, 0.7, 1e-3);
}

}  // namespace
}  // namespace rice::experiments
