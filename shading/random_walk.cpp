// Random-walk subsurface scattering in a sphere (random_walk.hpp).
#include "shading/random_walk.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "shading/fresnel.hpp"
#include "shading/scattering.hpp"

namespace rice::shading {
namespace {

using Eigen::Vector3d;

void check(const Medium& m, double radius, const RandomWalkOptions& o) {
  if (!(radius > 0.0) || !(m.scattering >= 0.0) || !(m.absorption >= 0.0) || !(m.scattering + m.absorption > 0.0) ||
      !(std::abs(m.anisotropy) < 1.0) || !(m.refractive_index > 0.0) || o.photons < 1 || o.bins < 1 || o.batch < 1) {
    throw std::invalid_argument(
        "sphere_exitance: needs radius > 0, scattering and absorption >= 0 with a positive sum, |anisotropy| < 1, "
        "refractive index > 0, and photons, bins and batch >= 1");
  }
}

// Distance along unit d from x (inside or on the sphere) to the sphere.
double exit_distance(const Vector3d& x, const Vector3d& d, double radius) {
  const double b = x.dot(d);
  return -b + std::sqrt(std::max(0.0, b * b - x.squaredNorm() + radius * radius));
}

struct BatchTally {
  std::vector<double> bins;  // escaped weight per θ bin
  double entered = 0.0, escaped = 0.0, ballistic = 0.0;
};

BatchTally trace_batch(const Medium& medium, double radius, int bins, long long photons, std::uint64_t stream) {
  std::mt19937_64 rng(stream);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double sigma_t = medium.scattering + medium.absorption;
  const double survival = medium.scattering / sigma_t;
  const double eta = medium.refractive_index;
  constexpr int kMaxEvents = 1'000'000;
  BatchTally tally{std::vector<double>(bins, 0.0)};
  for (long long p = 0; p < photons; ++p) {
    // Uniform over the beam's disk; the beam travels along −z, so ℓ = +z.
    const double rho = radius * std::sqrt(unit(rng)), angle = 2 * std::numbers::pi * unit(rng);
    const double px = rho * std::cos(angle), py = rho * std::sin(angle);
    Vector3d x(px, py, std::sqrt(std::max(0.0, radius * radius - rho * rho)));
    const Vector3d normal = x / radius;
    const double cos_in = normal.z();
    double weight = 1.0 - fresnel_reflectance(cos_in, eta);  // the rest is the specular lobe
    tally.entered += weight;
    Vector3d d = refract(Vector3d(0, 0, -1), normal, eta);
    bool scattered = false;
    for (int event = 0; event < kMaxEvents && weight > 0.0; ++event) {
      const double to_boundary = exit_distance(x, d, radius);
      const double free_path = -std::log(1.0 - unit(rng)) / sigma_t;
      if (free_path < to_boundary) {
        x += free_path * d;
        weight *= survival;
        d = rotate_about(d, sample_henyey_greenstein(medium.anisotropy, unit(rng)), 2 * std::numbers::pi * unit(rng));
        scattered = true;
      } else {
        x = (x + to_boundary * d).normalized() * radius;
        const Vector3d n = x / radius;
        const double reflectance = fresnel_reflectance(d.dot(n), 1.0 / eta);
        const double out = weight * (1.0 - reflectance);
        if (scattered) {
          const double theta = std::acos(std::clamp(n.z(), -1.0, 1.0));
          tally.bins[std::min(bins - 1, static_cast<int>(theta / std::numbers::pi * bins))] += out;
          tally.escaped += out;
        } else {
          tally.ballistic += out;
        }
        weight *= reflectance;
        d -= 2.0 * d.dot(n) * n;
      }
      if (weight < 1e-4) {  // Russian roulette keeps the estimate unbiased
        if (unit(rng) < 0.1) weight *= 10.0;
        else weight = 0.0;
      }
    }
  }
  return tally;
}

}  // namespace

ExitanceProfile sphere_exitance(const Medium& medium, double radius, const RandomWalkOptions& options) {
  check(medium, radius, options);
  const auto start = std::chrono::steady_clock::now();
  const long long batch_count = (options.photons + options.batch - 1) / options.batch;
  std::vector<BatchTally> batches(static_cast<std::size_t>(batch_count));
  tbb::parallel_for(0LL, batch_count, [&](long long b) {
    const long long photons = std::min<long long>(options.batch, options.photons - b * options.batch);
    batches[b] = trace_batch(medium, radius, options.bins, photons, split_mix(options.seed * 0x100000001b3ULL + b));
  });

  // M/E in bin k: escaped weight / (2 N Δcos θ_k) (flux E π r² spread over N photons, bin
  // area 2π r² Δcos θ_k). Its standard error from the spread of the per-batch estimates.
  ExitanceProfile profile;
  const int bins = options.bins;
  profile.photons = options.photons;
  profile.theta.resize(bins);
  profile.exitance.assign(bins, 0.0);
  profile.standard_error.assign(bins, 0.0);
  std::vector<double> sum_sq(bins, 0.0);
  for (int k = 0; k < bins; ++k) {
    const double lo = std::numbers::pi * k / bins, hi = std::numbers::pi * (k + 1) / bins;
    profile.theta[k] = 0.5 * (lo + hi);
    const double band = std::cos(lo) - std::cos(hi);
    for (std::size_t b = 0; b < batches.size(); ++b) {
      const double photons = static_cast<double>(std::min<long long>(options.batch, options.photons - b * options.batch));
      const double estimate = batches[b].bins[k] / (2.0 * photons * band);
      profile.exitance[k] += batches[b].bins[k] / (2.0 * options.photons * band);
      sum_sq[k] += estimate * estimate;
    }
    const double n = static_cast<double>(batches.size());
    if (n > 1) {
      const double variance = std::max(0.0, sum_sq[k] / n - profile.exitance[k] * profile.exitance[k]) * n / (n - 1);
      profile.standard_error[k] = std::sqrt(variance / n);
    }
  }
  for (const auto& b : batches) {
    profile.entered += b.entered / options.photons;
    profile.escaped += b.escaped / options.photons;
    profile.ballistic += b.ballistic / options.photons;
  }
  profile.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return profile;
}

}  // namespace rice::shading
