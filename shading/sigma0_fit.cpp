// Least-squares σ0 (sigma0_fit.hpp).
#include "shading/sigma0_fit.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "shading/cdrf.hpp"

namespace rice::shading {
namespace {

struct Residual {
  double amplitude, sum_of_squares;
};

// For fixed σ0 the best A = Σ m f / Σ f², and the residual follows.
Residual best_amplitude(const std::vector<ExitanceSample>& samples, double sigma0) {
  std::vector<double> model(samples.size());
  double mf = 0.0, ff = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& s = samples[k];
    model[k] = cdrf_integral(std::cos(s.theta), sigma0 * std::abs(s.curvature));
    mf += s.exitance * model[k];
    ff += model[k] * model[k];
  }
  const double amplitude = ff > 0.0 ? mf / ff : 0.0;
  double sum = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double r = amplitude * model[k] - samples[k].exitance;
    sum += r * r;
  }
  return {amplitude, sum};
}

struct MinimizerDeleter {
  void operator()(gsl_min_fminimizer* m) const { gsl_min_fminimizer_free(m); }
};

}  // namespace

Sigma0Fit fit_sigma0(const std::vector<ExitanceSample>& samples, double sigma0_min, double sigma0_max) {
  if (samples.size() < 2 || !(sigma0_min > 0.0) || !(sigma0_max > sigma0_min)) {
    throw std::invalid_argument("fit_sigma0: needs two samples or more and 0 < sigma0_min < sigma0_max");
  }
  // Coarse scan in log σ0, then Brent inside the bracket around the best grid point.
  constexpr int kGrid = 48;
  const double lo = std::log(sigma0_min), hi = std::log(sigma0_max);
  std::vector<double> cost(kGrid + 1);
  int best = 0;
  for (int k = 0; k <= kGrid; ++k) {
    cost[k] = best_amplitude(samples, std::exp(lo + (hi - lo) * k / kGrid)).sum_of_squares;
    if (cost[k] < cost[best]) best = k;
  }
  double log_sigma0 = lo + (hi - lo) * best / kGrid;
  const bool at_bound = best == 0 || best == kGrid;
  if (!at_bound) {
    gsl_set_error_handler_off();  // statuses, not aborts
    auto objective = [](double x, void* p) {
      return best_amplitude(*static_cast<const std::vector<ExitanceSample>*>(p), std::exp(x)).sum_of_squares;
    };
    gsl_function f{objective, const_cast<std::vector<ExitanceSample>*>(&samples)};
    std::unique_ptr<gsl_min_fminimizer, MinimizerDeleter> minimizer(gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent));
    const double a = lo + (hi - lo) * (best - 1) / kGrid, b = lo + (hi - lo) * (best + 1) / kGrid;
    if (gsl_min_fminimizer_set_with_values(minimizer.get(), &f, log_sigma0, cost[best], a, cost[best - 1], b,
                                           cost[best + 1]) == GSL_SUCCESS) {
      for (int iteration = 0; iteration < 100; ++iteration) {
        if (gsl_min_fminimizer_iterate(minimizer.get()) != GSL_SUCCESS) break;
        if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(minimizer.get()),
                                  gsl_min_fminimizer_x_upper(minimizer.get()), 1e-6, 0.0) == GSL_SUCCESS) {
          break;
        }
      }
      log_sigma0 = gsl_min_fminimizer_x_minimum(minimizer.get());
    }
  }
  const double sigma0 = std::exp(log_sigma0);
  const Residual r = best_amplitude(samples, sigma0);
  return {sigma0, r.amplitude, std::sqrt(r.sum_of_squares / samples.size()), at_bound};
}

}  // namespace rice::shading
