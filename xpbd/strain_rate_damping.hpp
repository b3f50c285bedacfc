// Damping that reaches every strain rate of a tetrahedron: the dissipation potential
//
//   D = ½ τ Ė : 𝒞 : Ė,    Ė = sym(FᵀḞ) (the Green strain rate),                        (1)
//
// with 𝒞 the isotropic small-strain elasticity tensor of the material (Lamé μ and λ_L), i.e.
// Rayleigh stiffness-proportional damping whose matrix is τ times the material's stiffness,
// measured in the current frame so that rigid motion (Ė = 0) is not damped. Near rest every
// vibration mode of frequency ω then decays at the modal Rayleigh rate τ ω² / 2.
//
// The Neo-Hookean pair's own Rayleigh damping (D = ½ Ċᵀ β Ċ on C_D = ‖F‖ and C_H = det F,
// XPBD eq. 26) damps the rates of ‖F‖ and det F only, which are second order in a shear or a
// bend about rest; (1) damps them at first order.
//
// Over one step of h, with F frozen at the step's start Fⁿ and Ḟ ≈ (F − Fⁿ)/h, the step's
// dissipation is hD per unit volume, and a tet of rest volume V adds to the step's potential
//
//   Ψ = (τ V / h) φ(ΔF),   φ = ½ ε : 𝒞 : ε = μ ‖ε‖² + ½ λ_L (tr ε)²,   ε = sym(Fⁿᵀ ΔF),      (2)
//
// ΔF = F − Fⁿ. Ψ is quadratic in the positions and convex (𝒞 is positive definite for μ > 0,
// 3λ_L + 2μ > 0), so both solvers use its exact derivatives: the reference adds it to the
// Newton energy, vertex block descent minimises it by vertex (XPBD refuses it: solver.hpp). Stateless
// kernels in ΔF; derivatives in the positions follow from tet_stencil.hpp.
#pragma once

#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {

/// ε = sym(Fⁿᵀ ΔF), the strain increment of a step (h Ė).
inline Mat3 strain_increment(const Mat3& F_start, const Mat3& dF) {
  const Mat3 G = F_start.transpose() * dF;
  return 0.5 * (G + G.transpose());
}

/// φ of eq. (2).
inline double strain_rate_damping_value(const Mat3& F_start, const Mat3& dF, double mu, double lambda_lame) {
  const Mat3 e = strain_increment(F_start, dF);
  return mu * e.squaredNorm() + 0.5 * lambda_lame * e.trace() * e.trace();
}

/// ∂φ/∂ΔF = Fⁿ σ(ε), σ(ε) = 2μ ε + λ_L tr(ε) I the linear stress of the strain increment.
inline Mat3 strain_rate_damping_dF(const Mat3& F_start, const Mat3& dF, double mu, double lambda_lame) {
  const Mat3 e = strain_increment(F_start, dF);
  return F_start * (2.0 * mu * e + lambda_lame * e.trace() * Mat3::Identity());
}

/// ∂²φ/∂vec(ΔF)², constant within a step: column q is vec(∂φ/∂ΔF) at ΔF = the q-th unit matrix.
Mat9 strain_rate_damping_d2F(const Mat3& F_start, double mu, double lambda_lame);

/// ∂²φ/∂x_k² for the particle with stencil weights b (tet_stencil.hpp): with ΔF = δ bᵀ,
/// φ = ½ uᵀ (μ‖b‖² I + (μ + λ_L) b bᵀ) u, u = Fⁿᵀ δ, so the block is Fⁿ (…) Fⁿᵀ.
inline Mat3 strain_rate_damping_vertex_hessian(const Mat3& F_start, const Vec3& b, double mu, double lambda_lame) {
  const Mat3 inner = mu * b.squaredNorm() * Mat3::Identity() + (mu + lambda_lame) * b * b.transpose();
  return F_start * inner * F_start.transpose();
}

}  // namespace rice::xpbd
