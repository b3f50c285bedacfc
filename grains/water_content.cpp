// Peleg, Arrhenius and eq. 4 fits with GSL (see water_content.hpp).
#include "grains/water_content.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace rice::grains {
namespace {

constexpr double kKelvin = 273.15;

struct LinearFit {
  double intercept = 0.0, slope = 0.0, rms_residual = 0.0, r_squared = 0.0;
};

// y = intercept + slope x by GSL ordinary least squares.
LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  LinearFit fit;
  double cov00 = 0, cov01 = 0, cov11 = 0, sum_squares = 0;
  if (gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &fit.intercept, &fit.slope, &cov00, &cov01, &cov11,
                     &sum_squares) != GSL_SUCCESS)
    throw std::runtime_error("linear least squares failed");
  double mean = 0.0, total = 0.0;
  for (double v : y) mean += v / double(y.size());
  for (double v : y) total += (v - mean) * (v - mean);
  fit.rms_residual = std::sqrt(sum_squares / double(x.size()));
  fit.r_squared = total > 0.0 ? 1.0 - sum_squares / total : 1.0;
  return fit;
}

// Peleg residuals r_i = t_i / (k1 + k2 t_i) − W_i and their Jacobian.
struct PelegData {
  const std::vector<double>& minutes;
  const std::vector<double>& absorption;
};

int peleg_residual(const gsl_vector* k, void* data, gsl_vector* r) {
  const auto& d = *static_cast<const PelegData*>(data);
  for (size_t i = 0; i < d.minutes.size(); ++i) {
    const double t = d.minutes[i];
    gsl_vector_set(r, i, t / (gsl_vector_get(k, 0) + gsl_vector_get(k, 1) * t) - d.absorption[i]);
  }
  return GSL_SUCCESS;
}

int peleg_jacobian(const gsl_vector* k, void* data, gsl_matrix* J) {
  const auto& d = *static_cast<const PelegData*>(data);
  for (size_t i = 0; i < d.minutes.size(); ++i) {
    const double t = d.minutes[i];
    const double denominator = gsl_vector_get(k, 0) + gsl_vector_get(k, 1) * t;
    gsl_matrix_set(J, i, 0, -t / (denominator * denominator));
    gsl_matrix_set(J, i, 1, -t * t / (denominator * denominator));
  }
  return GSL_SUCCESS;
}

PelegFit fit_peleg(double temperature_c, const std::vector<double>& minutes, const std::vector<double>& absorption) {
  // Start from the linearised model t/W = k1 + k2 t, then minimise the absorption residuals.
  std::vector<double> ratio(minutes.size());
  for (size_t i = 0; i < minutes.size(); ++i) ratio[i] = minutes[i] / absorption[i];
  const LinearFit start = fit_line(minutes, ratio);

  PelegData data{minutes, absorption};
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = peleg_residual;
  fdf.df = peleg_jacobian;
  fdf.n = minutes.size();
  fdf.p = 2;
  fdf.params = &data;
  gsl_multifit_nlinear_parameters parameters = gsl_multifit_nlinear_default_parameters();
  gsl_multifit_nlinear_workspace* workspace =
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &parameters, fdf.n, fdf.p);
  gsl_vector* k = gsl_vector_alloc(2);
  gsl_vector_set(k, 0, start.intercept);
  gsl_vector_set(k, 1, start.slope);
  gsl_multifit_nlinear_init(k, &fdf, workspace);
  const double start_norm = gsl_blas_dnrm2(gsl_multifit_nlinear_residual(workspace));
  int info = 0;
  const int status = gsl_multifit_nlinear_driver(200, 1e-10, 1e-10, 0.0, nullptr, nullptr, &info, workspace);
  PelegFit fit;
  fit.temperature_c = temperature_c;
  fit.k1 = gsl_vector_get(workspace->x, 0);
  fit.k2 = gsl_vector_get(workspace->x, 1);
  const double final_norm = gsl_blas_dnrm2(gsl_multifit_nlinear_residual(workspace));
  fit.rms_residual = final_norm / std::sqrt(double(fdf.n));
  fit.samples = static_cast<int>(fdf.n);
  gsl_vector_free(k);
  gsl_multifit_nlinear_free(workspace);
  // A start that is already the exact minimum (noise-free data) leaves the trust region no
  // step to accept, and the driver runs out of iterations there: not a failure.
  const bool converged = status == GSL_SUCCESS || final_norm <= start_norm * (1.0 + 1e-12);
  if (!converged || !(fit.k1 > 0.0) || !(fit.k2 > 0.0))
    throw std::runtime_error("Peleg fit at " + std::to_string(temperature_c) + " °C failed: " + gsl_strerror(status));
  return fit;
}

}  // namespace

double DampingFit::beta(double seconds) const { return std::pow(10.0, -(a * std::log10(seconds) + b)); }

WaterContentModel::WaterContentModel(const std::vector<AbsorptionSample>& samples, DampingReference reference)
    : reference_(reference) {
  gsl_set_error_handler_off();  // GSL errors come back as status codes, turned into exceptions
  std::map<double, std::pair<std::vector<double>, std::vector<double>>> by_temperature;
  for (const AbsorptionSample& s : samples) {
    if (!(s.soak_minutes > 0.0) || !(s.absorption_percent > 0.0))
      throw std::invalid_argument("water content: soaking times and absorptions must be positive");
    by_temperature[s.temperature_c].first.push_back(s.soak_minutes);
    by_temperature[s.temperature_c].second.push_back(s.absorption_percent);
  }
  if (by_temperature.size() < 2)
    throw std::invalid_argument("water content: need soaking curves at two or more temperatures");
  std::vector<double> inverse_kelvin, log_rate, celsius, k2;
  for (const auto& [temperature, curve] : by_temperature) {
    if (curve.first.size() < 3)
      throw std::invalid_argument("water content: need three or more points at " + std::to_string(temperature) + " °C");
    peleg_.push_back(fit_peleg(temperature, curve.first, curve.second));
    inverse_kelvin.push_back(1.0 / (temperature + kKelvin));
    log_rate.push_back(std::log(1.0 / peleg_.back().k1));
    celsius.push_back(temperature);
    k2.push_back(peleg_.back().k2);
  }
  const LinearFit arrhenius = fit_line(inverse_kelvin, log_rate);
  c0_ = arrhenius.intercept;
  c1_ = arrhenius.slope;
  const LinearFit saturation = fit_line(celsius, k2);
  d0_ = saturation.intercept;
  d1_ = saturation.slope;

  // Eq. 4 on the data points: log10(1/β_i) against log10(t_i [s]).
  reference_absorption_ = absorption_percent(reference_.soak_minutes, reference_.temperature_c);
  for (const auto& [temperature, curve] : by_temperature) {
    std::vector<double> log_seconds, log_inverse_beta;
    for (size_t i = 0; i < curve.first.size(); ++i) {
      log_seconds.push_back(std::log10(60.0 * curve.first[i]));
      log_inverse_beta.push_back(std::log10(curve.second[i] / (reference_.beta * reference_absorption_)));
    }
    const LinearFit line = fit_line(log_seconds, log_inverse_beta);
    damping_.push_back({temperature, line.slope, line.intercept, line.rms_residual, line.r_squared,
                        static_cast<int>(log_seconds.size())});
  }
}

double WaterContentModel::absorption_percent(double soak_minutes, double temperature_c) const {
  const double k1 = 1.0 / std::exp(c0_ + c1_ / (temperature_c + kKelvin));
  const double k2 = d0_ + d1_ * temperature_c;
  return soak_minutes / (k1 + k2 * soak_minutes);
}

double WaterContentModel::beta(double soak_minutes, double temperature_c) const {
  return reference_.beta * reference_absorption_ / absorption_percent(soak_minutes, temperature_c);
}

double WaterContentModel::cohesion_ratio(double stickiness, double soak_minutes, double temperature_c) const {
  return stickiness * absorption_percent(soak_minutes, temperature_c) / reference_absorption_;
}

double WaterContentModel::scattering_sigma0(double absorption_percent) {
  // `rice study cdrf` (5 °C soaks of 15–240 min, spheres of 0.5–4 mm, 2e5 photons each):
  // the fit's RMS is 0.009 in ln σ0 (tests/validation/test_cdrf_law.cpp re-fits one point).
  constexpr double s0 = -7.6986, s1 = 0.03009;
  return std::exp(s0 + s1 * absorption_percent);
}

double WaterContentModel::cdrf_albedo(double absorption_percent) {
  constexpr double a0 = 0.7887, a1 = -0.00244;  // `rice study cdrf`, as for σ0
  return a0 + a1 * absorption_percent;
}

GrainOptics WaterContentModel::optics(double absorption_percent) {
  constexpr double kWaterIndex = 1.333, kStarchIndex = 1.53;
  constexpr double kWaterDensity = 1000.0, kStarchDensity = 1500.0;
  const double water_volume = absorption_percent / 100.0 / kWaterDensity;
  const double water_fraction = water_volume / (water_volume + 1.0 / kStarchDensity);
  return {.reduced_scattering = 12e3 * std::exp(-absorption_percent / 25.0),
          .absorption = 10.0,
          .refractive_index = water_fraction * kWaterIndex + (1.0 - water_fraction) * kStarchIndex};
}

}  // namespace rice::grains
