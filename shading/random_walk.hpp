// Brute-force subsurface scattering: the reference the CDRF is fitted to and checked against.
//
// Photons from a distant directional light enter a homogeneous medium through a smooth
// dielectric boundary (Fresnel reflection and Snell refraction), random-walk inside it
// (exponential free paths in σ_t = σ_s + σ_a, Henyey–Greenstein scattering, survival σ_s/σ_t
// as a weight), and meet the boundary again, where Fresnel decides between internal
// reflection and escape. Where they escape is tallied against θ, the angle between the
// surface normal there and the direction to the light. The light reflected at the first
// surface is the specular lobe, and light that crosses the medium without scattering is
// refraction through a clear body: neither is subsurface scattering, neither is tallied.
//
// Tally: exitance over irradiance, M(θ)/E, with E the irradiance on a surface facing the
// light. A Lambertian surface of albedo A would give A max(cos θ, 0); the CDRF predicts
// A f_r(θ, σ0 κ) (cdrf.hpp), which is what sigma0_fit.hpp fits.
//
// Written by hand: no library in reach does volumetric random walks.
#pragma once

#include <cstdint>
#include <vector>

namespace rice::shading {

/// Optical parameters of a homogeneous medium, SI units.
struct Medium {
  double scattering = 0.0;        ///< σ_s [1/m]
  double absorption = 0.0;        ///< σ_a [1/m]
  double anisotropy = 0.0;        ///< g of Henyey–Greenstein, in (−1, 1)
  double refractive_index = 1.0;  ///< η inside, relative to outside
};

/// Exitance against θ on a sphere, in `bins` equal steps of θ over [0, π].
struct ExitanceProfile {
  std::vector<double> theta;           ///< bin centres [rad]
  std::vector<double> exitance;        ///< M/E per bin
  std::vector<double> standard_error;  ///< of M/E, from the spread between photon batches
  double entered = 0.0;                ///< fraction of the beam refracted into the medium
  double escaped = 0.0;                ///< fraction of the beam that came out after scattering
  double ballistic = 0.0;              ///< fraction that came out without scattering
  long long photons = 0;
  double seconds = 0.0;
};

struct RandomWalkOptions {
  long long photons = 1'000'000;
  int bins = 36;
  std::uint64_t seed = 1;
  /// Photons are traced in batches of this size, each from its own random stream, so the
  /// result does not depend on the thread count.
  int batch = 10'000;
};

/// Sphere of `radius` [m] lit along −z by a beam filling its silhouette. Throws
/// std::invalid_argument for a non-positive radius, negative coefficients, σ_t = 0,
/// |g| ≥ 1, η ≤ 0, or photon and bin counts below 1.
ExitanceProfile sphere_exitance(const Medium& medium, double radius, const RandomWalkOptions& options = {});

}  // namespace rice::shading
