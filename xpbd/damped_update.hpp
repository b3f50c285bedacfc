// The XPBD multiplier update with Rayleigh damping: the one formula every compliant
// constraint uses (Macklin, Müller & Chentanez 2016, "XPBD", eq. 26), for a single constraint
// and for a pair of constraints solved jointly.
#pragma once

#include <cmath>

#include "xpbd/types.hpp"

namespace rice::xpbd {

/// Time-step-scaled compliance and damping of one constraint, XPBD §4–5:
/// α̃ = α / h², β̃ = h² β, γ = α̃ β̃ / h = α β / h.
/// α is the compliance (inverse stiffness) and β the damping coefficient of the Rayleigh
/// dissipation D = ½ Ċᵀ β Ċ, so that the damping force is −∇Cᵀ β Ċ.
struct ScaledCompliance {
  double alpha_tilde;
  double gamma;
};

inline ScaledCompliance scale_compliance(double alpha, double beta, double h) {
  return {alpha / (h * h), alpha * beta / h};
}

/// XPBD eq. (26):
///   Δλ = (−C − α̃ λ − γ ∇C (x − xⁿ)) / ((1 + γ) ∇C M⁻¹ ∇Cᵀ + α̃)
/// `grad_dot_dx` is ∇C (x − xⁿ), `grad_w_grad` is ∇C M⁻¹ ∇Cᵀ. Returns 0 when the constraint
/// cannot move (all its particles pinned and α̃ = 0).
inline double damped_delta_lambda(double C, double lambda, const ScaledCompliance& s,
                                  double grad_dot_dx, double grad_w_grad) {
  const double denominator = (1.0 + s.gamma) * grad_w_grad + s.alpha_tilde;
  if (denominator <= 0.0) return 0.0;
  return (-C - s.alpha_tilde * lambda - s.gamma * grad_dot_dx) / denominator;
}

/// Eq. (26) for two constraints on the same particles solved together (the Neo-Hookean pair,
/// Macklin & Müller 2021 §5): with G the 2×n stacked gradients and Γ = diag(γ),
///   ((I + Γ) G M⁻¹ Gᵀ + diag(α̃)) Δλ = −C − diag(α̃) λ − Γ G (x − xⁿ).
/// `gwg` is G M⁻¹ Gᵀ (symmetric). When the 2×2 system is singular (the two gradients
/// parallel and α̃ = 0) only the second constraint is solved, alone.
inline Vec2 damped_delta_lambda_pair(const Vec2& C, const Vec2& lambda,
                                     const ScaledCompliance& s0, const ScaledCompliance& s1,
                                     const Vec2& grad_dot_dx, const Mat2& gwg) {
  Mat2 A;
  A << (1.0 + s0.gamma) * gwg(0, 0) + s0.alpha_tilde, (1.0 + s0.gamma) * gwg(0, 1),
      (1.0 + s1.gamma) * gwg(1, 0), (1.0 + s1.gamma) * gwg(1, 1) + s1.alpha_tilde;
  const Vec2 rhs(-C[0] - s0.alpha_tilde * lambda[0] - s0.gamma * grad_dot_dx[0],
                 -C[1] - s1.alpha_tilde * lambda[1] - s1.gamma * grad_dot_dx[1]);
  const double det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
  const double scale = std::abs(A(0, 0) * A(1, 1)) + std::abs(A(0, 1) * A(1, 0));
  if (std::abs(det) <= 1e-12 * scale) {  // false for NaN, which then reaches the caller
    return Vec2(0.0, A(1, 1) > 0.0 ? rhs[1] / A(1, 1) : 0.0);
  }
  return Vec2((A(1, 1) * rhs[0] - A(0, 1) * rhs[1]) / det,
              (A(0, 0) * rhs[1] - A(1, 0) * rhs[0]) / det);
}

}  // namespace rice::xpbd
