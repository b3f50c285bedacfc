// CDRF (shading/cdrf.hpp): quadrature against the closed-form Fourier series, its limits and
// invariants, and the bilinear table against direct integration.
#include "shading/cdrf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace rice::shading {
namespace {


TEST(Cdrf, QuadratureMatchesTheFourierSeries) {
  for (double sigma : {0.01, 0.05, 0.2, 0.5, 1.0, 2.0, 4.0, 6.0}) {
    for (double c = -1.0; c <= 1.0; c += 0.125) {
      EXPECT_NEAR(cdrf_integral(c, sigma), cdrf_series(c, sigma), 1e-12) << "cos theta " << c << ", sigma " << sigma;
    }
  }
}

TEST(Cdrf, ZeroWidthIsTheClampedCosine) {
  for (double c = -1.0; c <= 1.0; c += 0.0625) {
    EXPECT_EQ(cdrf_integral(c, 0.0), std::max(c, 0.0));
    // A narrow Gaussian moves f_r by at most σ/sqrt(2π), the value it takes at the terminator.
    const double sigma = 1e-4;
    EXPECT_LE(std::abs(cdrf_integral(c, sigma) - std::max(c, 0.0)), sigma / std::sqrt(2 * std::numbers::pi) + 1e-12);
  }
  EXPECT_NEAR(cdrf_integral(0.0, 1e-4), 1e-4 / std::sqrt(2 * std::numbers::pi), 1e-12);
}

// The odd part of f_r is the blurred cosine itself: f(θ) − f(π − θ) = exp(−σ²/2) cos θ.
TEST(Cdrf, OddPartIsTheDampedCosine) {
  for (double sigma : {0.01, 0.3, 1.0, 3.0}) {
    for (double c : {0.0, 0.1, 0.5, 0.9, 1.0}) {
      EXPECT_NEAR(cdrf_integral(c, sigma) - cdrf_integral(-c, sigma), std::exp(-sigma * sigma / 2) * c, 1e-12);
    }
  }
}

// ∫ f_r dθ over the circle is the clamped cosine's 2 for every width; over a sphere lit from
// one side, 2π ∫_0^π f_r sin θ dθ grows from π (σ = 0) to 4 (σ → ∞), by the series:
// 2π [2/π + Σ_{even n ≥ 2} a_n e^{−n²σ²/2} 2 / (1 − n²)].
double integrate_over_theta(double sigma, bool sphere) {
  const int n = 4000;  // midpoint rule; the integrand is smooth for σ > 0
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double theta = std::numbers::pi * (k + 0.5) / n;
    sum += cdrf_integral(std::cos(theta), sigma) * (sphere ? 2 * std::numbers::pi * std::sin(theta) : 2.0);
  }
  return sum * std::numbers::pi / n;
}

double sphere_energy_series(double sigma) {
  double sum = 2.0 / std::numbers::pi;
  for (int n = 2; n < 4000; n += 2) {
    const double a_n = ((n / 2) % 2 == 1 ? 2.0 : -2.0) / (std::numbers::pi * (n * n - 1.0));
    sum += a_n * std::exp(-n * n * sigma * sigma / 2) * 2.0 / (1.0 - n * n);
  }
  return 2 * std::numbers::pi * sum;
}

TEST(Cdrf, EnergyOnTheCircleIsConservedAndOnTheSphereFollowsTheSeries) {
  for (double sigma : {0.1, 0.5, 1.5, 6.0}) {
    EXPECT_NEAR(integrate_over_theta(sigma, false), 2.0, 1e-7) << "sigma " << sigma;
    EXPECT_NEAR(integrate_over_theta(sigma, true), sphere_energy_series(sigma), 1e-6) << "sigma " << sigma;
  }
  EXPECT_NEAR(sphere_energy_series(1e-3), std::numbers::pi, 1e-5);
  EXPECT_NEAR(sphere_energy_series(6.0), 4.0, 1e-7);
}

TEST(Cdrf, WideGaussianFlattensToOneOverPi) {
  for (double c : {-1.0, 0.0, 1.0}) EXPECT_NEAR(cdrf_integral(c, CdrfTable::kSigmaMax), 1 / std::numbers::pi, 2e-8);
}

TEST(Cdrf, RefusesArgumentsOutsideTheDomain) {
  EXPECT_THROW(cdrf_integral(1.5, 0.1), std::invalid_argument);
  EXPECT_THROW(cdrf_integral(0.5, -0.1), std::invalid_argument);
  EXPECT_THROW(cdrf_integral(std::nan(""), 0.1), std::invalid_argument);
  EXPECT_THROW(CdrfTable(1, 10), std::invalid_argument);
}

// Largest |table − integral| over random points with σ ≥ sigma_floor.
double table_error(const CdrfTable& table, double sigma_floor) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 4000; ++k) {
    const double c = 2 * unit(rng) - 1;
    const double sigma = sigma_floor + (CdrfTable::kSigmaMax - sigma_floor) * unit(rng);
    worst = std::max(worst, std::abs(table(c, sigma) - cdrf_integral(c, sigma)));
  }
  return worst;
}

TEST(CdrfTable, NodesHoldTheIntegralAndTheZeroWidthColumnIsExact) {
  const CdrfTable table(33, 17);
  EXPECT_NEAR(table(0.3, 0.0), 0.3, 1e-15);
  EXPECT_EQ(table(-0.3, 0.0), 0.0);
  for (const double c : {-1.0, -0.25, 0.0, 0.5, 1.0})
    for (const int j : {1, 5, 16}) {
      const double sigma = CdrfTable::kSigmaMax * j / 16;
      EXPECT_EQ(table(c, sigma), cdrf_series(c, sigma));
      EXPECT_NEAR(table(c, sigma), cdrf_integral(c, sigma), 1e-12);
    }
  EXPECT_EQ(table(0.5, 100.0), table(0.5, CdrfTable::kSigmaMax));  // clamped beyond σ_max
}

// Bilinear interpolation is second order away from the σ → 0 corner, where f_r bends on the
// scale σ around the terminator: doubling the nodes quarters the error there.
TEST(CdrfTable, LookupConvergesAtSecondOrder) {
  const double coarse = table_error(CdrfTable(65, 65), 0.1);
  const double fine = table_error(CdrfTable(129, 129), 0.1);
  EXPECT_LT(fine, 0.35 * coarse) << coarse << " -> " << fine;
  EXPECT_LT(fine, 1e-3);
}

}  // namespace
}  // namespace rice::shading
