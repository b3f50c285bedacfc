// The steps a random walk in a scattering medium is made of, shared by the sphere reference
// (random_walk.hpp) and the mesh bake (subsurface_bake.hpp).
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "shading/tangent_frame.hpp"

namespace rice::shading {

/// A direction at angle acos(mu) from unit d, at azimuth phi around it.
inline Eigen::Vector3d rotate_about(const Eigen::Vector3d& d, double mu, double phi) {
  const auto [u, v] = tangent_frame(d);
  const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  return mu * d + s * (std::cos(phi) * u + std::sin(phi) * v);
}

/// Cosine of the Henyey–Greenstein scattering angle for a uniform u, by inverting its CDF.
inline double sample_henyey_greenstein(double g, double u) {
  if (std::abs(g) < 1e-6) return 2.0 * u - 1.0;
  const double q = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
  return std::clamp((1.0 + g * g - q * q) / (2.0 * g), -1.0, 1.0);
}

/// SplitMix64: independent seeds for the photon batches from one seed.
inline std::uint64_t split_mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace rice::shading
