// Central finite differences for derivative checks: every analytic gradient and Hessian in
// the testbed is compared against these.
#pragma once

#include <Eigen/Core>
#include <functional>

namespace rice::test_support {

/// ∂f/∂x by central differences with step h.
inline Eigen::VectorXd fd_gradient(const std::function<double(const Eigen::VectorXd&)>& f,
                                   const Eigen::VectorXd& x, double h) {
  Eigen::VectorXd g(x.size());
  for (int i = 0; i < x.size(); ++i) {
    Eigen::VectorXd xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    g[i] = (f(xp) - f(xm)) / (2.0 * h);
  }
  return g;
}

/// ∂g/∂x (rows: components of g) by central differences with step h.
inline Eigen::MatrixXd fd_jacobian(
    const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& g, const Eigen::VectorXd& x,
    double h) {
  const Eigen::VectorXd g0 = g(x);
  Eigen::MatrixXd J(g0.size(), x.size());
  for (int i = 0; i < x.size(); ++i) {
    Eigen::VectorXd xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    J.col(i) = (g(xp) - g(xm)) / (2.0 * h);
  }
  return J;
}

/// ‖a − b‖ / max(‖a‖, ‖b‖, floor): relative error that does not blow up when both vanish.
inline double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double floor) {
  return (a - b).norm() / std::max({a.norm(), b.norm(), floor});
}

}  // namespace rice::test_support
