// Curvature-dependent reflectance function, CDRF (paper §4.4, eqs. 6–8; Kubo, Dobashi &
// Morishima 2010): subsurface scattering approximated by blurring the clamped cosine of the
// incident light over the angle θ between light and normal, with a Gaussian whose width
// σ = σ0 κ grows with the curvature κ:
//
//   f_r(θ, σ) = ∫ L_i(θ − φ) g(φ; σ) dφ,   L_i(θ) = max(cos θ, 0),               (6), (7)
//   g(φ; σ)   = exp(−φ² / 2σ²) / sqrt(2π σ²).                                    (8)
//
// The integral runs over the whole real line with L_i 2π-periodic (θ is an angle), so the
// convolution conserves the cosine's energy on the circle, ∫_{−π}^{π} f_r dθ = 2, for every
// σ. Its Fourier series (cdrf_series) is the closed form the tests check the quadrature
// against and the table is filled from: with a_n the cosine coefficients of L_i,
//   f_r(θ, σ) = Σ_n a_n exp(−n² σ² / 2) cos nθ,
//   a_0 = 1/π, a_1 = 1/2, a_n = 2 (−1)^{n/2+1} / (π (n² − 1)) for even n ≥ 2, 0 for odd n ≥ 3.
// Two consequences used in tests: f_r(θ) − f_r(π − θ) = exp(−σ²/2) cos θ exactly, and
// f_r → 1/π as σ grows (the n = 1 term is below 2e-8 from σ = 6 on).
#pragma once

#include <vector>

namespace rice::shading {

/// f_r(θ, σ) of eq. 6 by adaptive Gauss–Kronrod quadrature (GSL QAG), θ = acos(cos_theta).
/// Absolute error below 1e-12. Throws std::invalid_argument for |cos θ| > 1 or σ < 0.
double cdrf_integral(double cos_theta, double sigma);

/// The same function from its Fourier series, summed until the terms fall below 1e-15:
/// about 8/σ terms, so microseconds even at σ = 0.01 (QAG's cost at every σ).
double cdrf_series(double cos_theta, double sigma);

/// f_r tabulated on a uniform grid over cos θ ∈ [−1, 1] and σ ∈ [0, σ_max], read bilinearly.
/// σ beyond σ_max reads the σ_max column: there f_r is within 2e-8 of its limit 1/π.
class CdrfTable {
 public:
  static constexpr double kSigmaMax = 6.0;

  /// `cos_theta_nodes` and `sigma_nodes` ≥ 2; an odd cos θ count puts a node on cos θ = 0,
  /// where the σ = 0 column has its kink, so that column is read exactly.
  /// Every node is one cdrf_series call (within 1e-12 of cdrf_integral), the σ rows in parallel.
  CdrfTable(int cos_theta_nodes, int sigma_nodes);

  /// Bilinear lookup; cos θ is clamped to [−1, 1], σ to [0, σ_max].
  double operator()(double cos_theta, double sigma) const;

 private:
  int nc_, ns_;
  std::vector<double> values_;  // σ-major: node (i, j) at cos θ_i = −1 + 2i/(nc−1), σ_j = σ_max j/(ns−1)
};

}  // namespace rice::shading
