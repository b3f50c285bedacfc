// CDRF by quadrature, by Fourier series, and as a bilinear table (cdrf.hpp).
#include "shading/cdrf.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

namespace rice::shading {
namespace {

void check_arguments(double cos_theta, double sigma) {
  if (!(std::abs(cos_theta) <= 1.0) || !(sigma >= 0.0)) {
    throw std::invalid_argument("cdrf: needs |cos theta| <= 1 and sigma >= 0, got cos theta = " +
                                std::to_string(cos_theta) + ", sigma = " + std::to_string(sigma));
  }
}

struct Integrand {
  double theta, sigma;
};

// L_i(θ − φ) g(φ; σ) on a lobe of L_i, where the clamp is inactive (eqs. 7, 8).
double lobe_integrand(double phi, void* params) {
  const auto& p = *static_cast<const Integrand*>(params);
  const double s2 = p.sigma * p.sigma;
  return std::cos(p.theta - phi) * std::exp(-phi * phi / (2.0 * s2)) / std::sqrt(2.0 * std::numbers::pi * s2);
}

struct WorkspaceDeleter {
  void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};

}  // namespace

double cdrf_integral(double cos_theta, double sigma) {
  check_arguments(cos_theta, sigma);
  if (sigma == 0.0) return std::max(cos_theta, 0.0);
  constexpr int kLimit = 200;
  static const bool handler_off = (gsl_set_error_handler_off(), true);  // errors come back as statuses
  (void)handler_off;
  thread_local std::unique_ptr<gsl_integration_workspace, WorkspaceDeleter> workspace(
      gsl_integration_workspace_alloc(kLimit));
  Integrand params{std::acos(cos_theta), sigma};
  gsl_function f{&lobe_integrand, &params};
  // The Gaussian beyond 12σ carries exp(−72) of its mass; each lobe of L_i (where
  // cos(θ − φ) > 0, i.e. φ ∈ θ + 2πk ± π/2) that meets [−12σ, 12σ] is integrated on its own,
  // so QAG never sees the clamp's kink.
  const double reach = 12.0 * sigma;
  const int k_first = static_cast<int>(std::floor((-reach - params.theta - std::numbers::pi / 2) / (2 * std::numbers::pi)));
  const int k_last = static_cast<int>(std::ceil((reach - params.theta + std::numbers::pi / 2) / (2 * std::numbers::pi)));
  double sum = 0.0;
  for (int k = k_first; k <= k_last; ++k) {
    const double lo = std::max(params.theta + 2 * std::numbers::pi * k - std::numbers::pi / 2, -reach);
    const double hi = std::min(params.theta + 2 * std::numbers::pi * k + std::numbers::pi / 2, reach);
    if (lo >= hi) continue;
    double value = 0.0, error = 0.0;
    const int status = gsl_integration_qag(&f, lo, hi, 1e-14, 1e-13, kLimit, GSL_INTEG_GAUSS21,
                                           workspace.get(), &value, &error);
    // Round-off that stops QAG short of 1e-14 on a lobe holding almost none of the Gaussian
    // is accepted while its error estimate stays below 1e-13.
    if (status != GSL_SUCCESS && !(status == GSL_EROUND && error < 1e-13)) {
      throw std::runtime_error(std::string("cdrf_integral: QAG failed: ") + gsl_strerror(status));
    }
    sum += value;
  }
  return sum;
}

double cdrf_series(double cos_theta, double sigma) {
  check_arguments(cos_theta, sigma);
  if (sigma == 0.0) return std::max(cos_theta, 0.0);
  const double theta = std::acos(cos_theta);
  const double s2 = sigma * sigma / 2.0;
  double sum = 1.0 / std::numbers::pi + 0.5 * std::exp(-s2) * cos_theta;
  for (int n = 2;; n += 2) {
    const double damping = std::exp(-n * n * s2);
    // Tail bound: Σ_{m ≥ n} |a_m| e^{−m²σ²/2} ≤ e^{−n²σ²/2} (2/π) / (n − 1).
    if (damping * 2.0 / (std::numbers::pi * (n - 1)) < 1e-15) break;
    const double a_n = ((n / 2) % 2 == 1 ? 2.0 : -2.0) / (std::numbers::pi * (n * n - 1.0));
    sum += a_n * damping * std::cos(n * theta);
  }
  return sum;
}

CdrfTable::CdrfTable(int cos_theta_nodes, int sigma_nodes) : nc_(cos_theta_nodes), ns_(sigma_nodes) {
  if (nc_ < 2 || ns_ < 2) throw std::invalid_argument("CdrfTable: needs at least 2 nodes along each axis");
  values_.resize(static_cast<std::size_t>(nc_) * ns_);
  // By the series: the 513 x 513 table of every render took 1.7 s by quadrature, 13 ms so.
  tbb::parallel_for(0, ns_, [&](int j) {
    const double sigma = kSigmaMax * j / (ns_ - 1);
    for (int i = 0; i < nc_; ++i) {
      const double cos_theta = std::clamp(-1.0 + 2.0 * i / (nc_ - 1), -1.0, 1.0);
      values_[static_cast<std::size_t>(j) * nc_ + i] = cdrf_series(cos_theta, sigma);
    }
  });
}

double CdrfTable::operator()(double cos_theta, double sigma) const {
  const double u = (std::clamp(cos_theta, -1.0, 1.0) + 1.0) * 0.5 * (nc_ - 1);
  const double v = std::clamp(sigma, 0.0, kSigmaMax) / kSigmaMax * (ns_ - 1);
  const int i = std::min(static_cast<int>(u), nc_ - 2);
  const int j = std::min(static_cast<int>(v), ns_ - 2);
  const double a = u - i, b = v - j;
  const double* row0 = &values_[static_cast<std::size_t>(j) * nc_ + i];
  const double* row1 = row0 + nc_;
  return (1 - b) * ((1 - a) * row0[0] + a * row0[1]) + b * ((1 - a) * row1[0] + a * row1[1]);
}

}  // namespace rice::shading
