// Water-content model (paper §3 and §4.2): soaking time and water temperature give the
// water absorption W (% of dry weight), which gives the constraint damping β of paper
// eq. 4 and the CDRF scattering width σ0 of eq. 8.
//
// Absorption: Peleg's model, W(t) = t / (k1 + k2 t) (Peleg 1988, J. Food Sci. 53:1216),
// fitted per temperature by nonlinear least squares (GSL multifit_nlinear, trust region);
// between temperatures k1 follows Arrhenius, ln(1/k1) = c0 + c1/T [K], and k2 (1/W at
// saturation) is linear in T [°C], both fitted by GSL linear least squares.
//
// Damping, eq. 4: log10(1/β) = a·log10(t) + b with t in seconds. The paper reads β off the
// absorption curves in log–log axes; we make that explicit as 1/β ∝ W(t), i.e.
//   β(t) = β_ref · W_ref / W(t),
// with β_ref the damping at a reference soak (10 °C, 120 min, the paper's Fig. 10), and fit
// a, b to the data points by GSL linear least squares in log–log. β is the stiffness-
// proportional Rayleigh coefficient expressed as a time (our solvers' `rayleigh_time`, so
// that each constraint's damping is β/α). β_ref is a PLACEHOLDER the scene work will tune.
//
// Cohesion (the paper's water-content constraint): the force to pull two touching grains
// apart, in grain weights, grows in proportion to the absorbed water,
//   F / (m g) = S · W(t, T) / W_ref,
// with S the cultivar's stickiness (cultivar.hpp) at the reference soak, where W = W_ref.
// Wetter grains carry more gelatinised surface starch, the glue (an ESTIMATE of the law's
// form; S is calibrated, the proportionality is not).
//
// Optics of a soaked grain, the medium of the shading module's subsurface reference:
//  - refractive index: the volume-weighted mean (Arago–Biot rule, an approximation) of water,
//    1.333, and starch granules, 1.53, with densities 1000 and 1500 kg/m³;
//  - reduced scattering μs' = 12 /mm · exp(−W / 25 %): an ESTIMATE. No measurement for rice is
//    in reach; the order is that of plant tissue (pear flesh: ~1 /mm at 500–1000 nm, Hu, Fu &
//    Ying 2017), higher for the chalky low-water grain. Water swells and gelatinises the
//    starch, narrowing the index steps that scatter, so μs' falls with W (the grain turns
//    translucent);
//  - absorption μa = 0.01 /mm: an ESTIMATE, the low end of plant tissue (pear: 0.01–0.06 /mm);
//    starch and water barely absorb visible light;
//  - isotropic scattering with μs = μs' (the similarity relation), as only μs' matters once
//    light has scattered a few times.
//
// σ0 (eq. 8): ln σ0 = s0 + s1 W, fitted by `rice study cdrf` (experiments/studies/cdrf_study.hpp) to
// the random-walk reference with the optics above; the constants are that study's output.
#pragma once

#include <vector>

#include "grains/absorption_table.hpp"

namespace rice::grains {

/// Peleg fit at one temperature: W(t) = t / (k1 + k2 t), t in minutes.
struct PelegFit {
  double temperature_c = 0.0;
  double k1 = 0.0;  ///< [min/%], 1/k1 is the initial absorption rate
  double k2 = 0.0;  ///< [1/%], 1/k2 is the absorption at saturation
  double rms_residual = 0.0;  ///< [%]
  int samples = 0;
  double absorption_percent(double minutes) const { return minutes / (k1 + k2 * minutes); }
};

/// Eq. 4 fit at one temperature: log10(1/β) = a·log10(t [s]) + b.
struct DampingFit {
  double temperature_c = 0.0;
  double a = 0.0;
  double b = 0.0;
  double rms_residual = 0.0;  ///< in log10 units
  double r_squared = 0.0;
  int samples = 0;
  /// β [s] after `seconds` of soaking.
  double beta(double seconds) const;
};

/// Reference point of the damping law: β_ref after soaking at (T_ref, t_ref).
struct DampingReference {
  double temperature_c = 10.0;
  double soak_minutes = 120.0;
  double beta = 2e-3;  ///< [s] PLACEHOLDER
};

/// Optical parameters of a soaked grain, SI units.
struct GrainOptics {
  double reduced_scattering = 0.0;  ///< μs' [1/m]
  double absorption = 0.0;          ///< μa [1/m]
  double refractive_index = 0.0;
};

class WaterContentModel {
 public:
  /// Fits every temperature of `samples` (at least two temperatures, three points each,
  /// times and absorptions positive). Throws std::invalid_argument otherwise.
  explicit WaterContentModel(const std::vector<AbsorptionSample>& samples, DampingReference reference = {});

  const std::vector<PelegFit>& peleg_fits() const { return peleg_; }
  const std::vector<DampingFit>& damping_fits() const { return damping_; }
  /// Arrhenius fit of k1: ln(1/k1) = c0 + c1 / T[K].
  double arrhenius_c0() const { return c0_; }
  double arrhenius_c1() const { return c1_; }

  /// W(t, T) [%] from the temperature-interpolated Peleg parameters.
  double absorption_percent(double soak_minutes, double temperature_c) const;
  /// β of eq. 4 from W: β_ref W_ref / W(t, T) [s].
  double beta(double soak_minutes, double temperature_c) const;
  /// Pull-off force of two touching grains in grain weights, S W(t, T) / W_ref.
  double cohesion_ratio(double stickiness, double soak_minutes, double temperature_c) const;
  /// σ0 of eq. 8 [m] (σ = σ0 κ in radians): exp(s0 + s1 W), fitted by `rice study cdrf`.
  static double scattering_sigma0(double absorption_percent);
  /// Albedo A of the CDRF (the fraction of light that comes back out): a0 + a1 W, fitted by
  /// `rice study cdrf` with σ0.
  static double cdrf_albedo(double absorption_percent);
  /// Optical parameters at water absorption W [%] (ESTIMATES; see the top of this file).
  static GrainOptics optics(double absorption_percent);

 private:
  std::vector<PelegFit> peleg_;
  std::vector<DampingFit> damping_;
  double c0_ = 0.0, c1_ = 0.0;  // Arrhenius fit of k1
  double d0_ = 0.0, d1_ = 0.0;  // k2 = d0 + d1 T
  DampingReference reference_;
  double reference_absorption_ = 0.0;
};

}  // namespace rice::grains
