// σ0 of eq. 8 fitted to a subsurface-scattering reference (paper §4.4: "σ0 minimises the RMS
// error with the obtained dataset f_r"). The model of an exitance sample at angle θ on a
// surface of curvature κ is A f_r(θ, σ0 κ) (cdrf.hpp): A, the fraction of light that comes
// back out (an albedo), is linear and solved in closed form for each σ0; σ0 is found by a
// scan over a log grid, refined with GSL's Brent minimiser.
#pragma once

#include <vector>

namespace rice::shading {

/// One point of the dataset: exitance over irradiance at angle θ on a surface of curvature κ.
struct ExitanceSample {
  double theta = 0.0;      ///< [rad], between the surface normal and the light
  double curvature = 0.0;  ///< κ [1/m]
  double exitance = 0.0;   ///< M/E
};

struct Sigma0Fit {
  double sigma0 = 0.0;     ///< [m]: σ = σ0 κ
  double amplitude = 0.0;  ///< A
  double rms = 0.0;        ///< RMS of A f_r − M/E over the samples
  bool at_bound = false;   ///< the minimum lies at an end of the search interval
};

/// Least-squares σ0 within [sigma0_min, sigma0_max] [m]. Throws std::invalid_argument for
/// fewer than two samples or a bad interval.
Sigma0Fit fit_sigma0(const std::vector<ExitanceSample>& samples, double sigma0_min, double sigma0_max);

}  // namespace rice::shading
