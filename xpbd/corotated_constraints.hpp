// The corotated material as two constraints per tetrahedron, an alternative to the stable
// Neo-Hookean pair (neo_hookean_constraints.hpp) with the same small-strain response:
//
//   deviatoric   C_D = ‖F − R‖_F,   α_D = 1 / (2 μ V)
//   hydrostatic  C_H = det F − 1,   α_H = 1 / (λ_L V)
//
// R is the rotation of F's polar decomposition (the rotation-variant one, det R = +1, also
// for an inverted F). U = ½ C_D²/α_D + ½ C_H²/α_H = V (μ ‖F − R‖² + λ_L/2 (det F − 1)²)
// linearises at F = I to μ ε:ε + λ_L/2 (tr ε)², linear elasticity with Lamé (μ, λ_L).
//
// Why it exists: both constraints are zero at rest, and ∇C_D = (F − R)/‖F − R‖ points along
// the strain. The Neo-Hookean C_D = ‖F‖ has gradient F/‖F‖ ∝ I at rest, so its shear
// stiffness lives only in λ_D ∇²C_D, the term XPBD's update drops; on sliver tets that made
// XPBD need 480 substeps a frame where this pair is stable at 20 (docs/known-limits.md).
//
// ∂(½‖F − R‖²)/∂F = F − R exactly (R maximises tr(RᵀF), so its variation drops out), hence
// ∂C_D/∂F = (F − R)/C_D; and ∂²(½‖F − R‖²)/∂F² = I₉ − ∂R/∂F with ∂R/∂F = Σ_i λ_i t_i t_iᵀ
// over the three twist modes of F = U Σ Vᵀ, t_i = vec(U T_i Vᵀ)/√2, λ_i = 2/(σ_j + σ_k)
// (Smith, de Goes & Kim 2019, "Analytic Eigensystems for Isotropic Distortion Energies", §5).
#pragma once

#include <Eigen/Geometry>

#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {

/// R of F = R S, the rotation nearest F (det R = +1), by a singular value decomposition.
Mat3 polar_rotation(const Mat3& F);

/// Refines q towards the polar rotation of F, the rotation that maximises tr(RᵀF). As in
/// Müller et al. 2016 ("A Robust Method to Extract the Rotational Part of Deformations") each
/// iteration turns R(q) about ω, along the torque τ = Σ_c r_c × f_c that aligns R's columns
/// with F's; here ω = H⁻¹τ, the Newton step with H = tr(B) I − sym B, B = F Rᵀ, the Hessian of
/// tr(RᵀF) in ω (Müller's τ/|Σ_c r_c · f_c| is H⁻¹τ for B = I with 3 for 2, and converges
/// linearly at a rate of ⅓). Where H is not positive definite (R far from F's rotation, or F
/// inverted) it takes Müller's step. Warm-started from the last substep it converges in one or
/// two iterations where an SVD costs several times more; Eigen has no warm-started polar
/// decomposition, hence this loop.
void refine_polar_rotation(const Mat3& F, Eigen::Quaterniond& q, int max_iterations = 20);

/// C_D = ‖F − R‖_F with R the polar rotation of F.
inline double corotated_deviatoric_value(const Mat3& F, const Mat3& R) { return (F - R).norm(); }

/// ∂C_D/∂F = (F − R)/‖F − R‖ (zero at C_D = 0, where C_D is not differentiable).
inline Mat3 corotated_deviatoric_dF(const Mat3& F, const Mat3& R) {
  const Mat3 D = F - R;
  const double norm = D.norm();
  return norm > 0.0 ? Mat3(D / norm) : Mat3::Zero();
}

/// ∂R/∂F as a 9 × 9 matrix on vec F (column-major), from the twist modes above.
Mat9 polar_rotation_dF(const Mat3& F);

/// ∂²C_D/∂F² = (I₉ − ∂R/∂F − ∇C_D ∇C_Dᵀ) / C_D (zero at C_D = 0).
Mat9 corotated_deviatoric_d2F(const Mat3& F);

/// C_H = det F − 1.
inline double corotated_hydrostatic_value(const Mat3& F) { return F.determinant() - 1.0; }

}  // namespace rice::xpbd
