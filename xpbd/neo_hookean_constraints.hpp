// The stable Neo-Hookean material as two constraints per tetrahedron
// (Macklin & Müller 2021, "A Constraint-based Formulation of Stable Neo-Hookean Materials"):
//
//   deviatoric   C_D = sqrt(tr FᵀF) = ‖F‖_F,   α_D = 1 / (μ V)
//   hydrostatic  C_H = det F − γ,   γ = 1 + μ/λ,   α_H = 1 / (λ V)
//
// so that U = ½ C_D²/α_D + ½ C_H²/α_H = V (μ/2 tr FᵀF + λ/2 (det F − γ)²). Neither constraint
// is zero at rest (C_D = √3, C_H = −μ/λ), but the forces cancel there: ∂U/∂F at F = I is
// V (μ I + λ(1 − γ) I) = 0. The energy at rest is the constant rest_energy_density · V.
// Stateless kernels with derivatives in F and in the 12 stencil coordinates.
#pragma once

#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {

/// γ = 1 + μ/λ, the rest value of det F that makes the pair stress-free at F = I.
inline double neo_hookean_gamma(double mu, double lambda) { return 1.0 + mu / lambda; }

/// Energy density of the pair at F = I: 3μ/2 + μ²/(2λ). Subtracted so that rest has U = 0.
inline double neo_hookean_rest_energy_density(double mu, double lambda) {
  return 1.5 * mu + 0.5 * mu * mu / lambda;
}

// --- deviatoric C_D = ‖F‖_F --------------------------------------------------------------

inline double neo_hookean_deviatoric_value(const Mat3& F) { return F.norm(); }

/// ∂C_D/∂F = F / ‖F‖ (zero at F = 0, where C_D is not differentiable).
inline Mat3 neo_hookean_deviatoric_dF(const Mat3& F) {
  const double norm = F.norm();
  return norm > 0.0 ? Mat3(F / norm) : Mat3::Zero();
}

/// ∂²C_D/∂F² = (I₉ − f fᵀ / ‖f‖²) / ‖f‖ with f = vec(F).
Mat9 neo_hookean_deviatoric_d2F(const Mat3& F);

/// ∂²C_D/∂x_k² for the particle with stencil weights b (tet_stencil.hpp): the contraction of
/// ∂²C_D/∂F² with b, (‖b‖² I − (F b)(F b)ᵀ / ‖F‖²) / ‖F‖, without forming the 9 × 9 matrix
/// (zero at F = 0).
inline Mat3 neo_hookean_deviatoric_vertex_hessian(const Mat3& F, const Vec3& b) {
  const double norm = F.norm();
  if (!(norm > 0.0)) return Mat3::Zero();
  const Vec3 Fb = F * b;
  return (b.squaredNorm() * Mat3::Identity() - Fb * Fb.transpose() / (norm * norm)) / norm;
}

// --- hydrostatic C_H = det F − γ ---------------------------------------------------------

inline double neo_hookean_hydrostatic_value(const Mat3& F, double gamma) {
  return F.determinant() - gamma;
}

/// ∂C_H/∂F = cof F.
inline Mat3 neo_hookean_hydrostatic_dF(const Mat3& F) { return cofactor(F); }

/// ∂²C_H/∂F² = ∂² det F / ∂F².
inline Mat9 neo_hookean_hydrostatic_d2F(const Mat3& F) { return determinant_hessian(F); }

// --- in the stencil coordinates x = [x0; x1; x2; x3] -------------------------------------

inline Vec12 neo_hookean_deviatoric_gradient(const Vec12& x, const Mat3& Dm_inv) {
  return gradient_from_dF(neo_hookean_deviatoric_dF(deformation_gradient(x, Dm_inv)), Dm_inv);
}

inline Vec12 neo_hookean_hydrostatic_gradient(const Vec12& x, const Mat3& Dm_inv) {
  return gradient_from_dF(neo_hookean_hydrostatic_dF(deformation_gradient(x, Dm_inv)), Dm_inv);
}

inline Mat12 neo_hookean_deviatoric_hessian(const Vec12& x, const Mat3& Dm_inv) {
  return hessian_from_d2F(neo_hookean_deviatoric_d2F(deformation_gradient(x, Dm_inv)), Dm_inv);
}

inline Mat12 neo_hookean_hydrostatic_hessian(const Vec12& x, const Mat3& Dm_inv) {
  return hessian_from_d2F(neo_hookean_hydrostatic_d2F(deformation_gradient(x, Dm_inv)), Dm_inv);
}

}  // namespace rice::xpbd
