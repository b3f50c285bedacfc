// Calculus on the four-particle stencil of a linear tetrahedron: the deformation gradient
// F = Ds Dm⁻¹ and the chain rule that turns derivatives with respect to F into derivatives
// with respect to the 12 particle coordinates. Shared by every per-tet constraint.
//
// Conventions: x = [x0; x1; x2; x3] (12-vector); Ds = [x1−x0, x2−x0, x3−x0];
// vec(F) stacks the columns of F (column-major), so index a + 3j is F(a, j).
#pragma once

#include "xpbd/types.hpp"

namespace rice::xpbd {

/// Edge matrix Ds = [x1 − x0, x2 − x0, x3 − x0].
inline Mat3 edge_matrix(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  Mat3 Ds;
  Ds.col(0) = x1 - x0;
  Ds.col(1) = x2 - x0;
  Ds.col(2) = x3 - x0;
  return Ds;
}

inline Mat3 edge_matrix(const Vec12& x) {
  return edge_matrix(x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), x.segment<3>(9));
}

/// Signed volume det(Ds) / 6; positive for a positively oriented tetrahedron.
inline double signed_volume(const Vec12& x) { return edge_matrix(x).determinant() / 6.0; }

/// Deformation gradient F = Ds Dm⁻¹ of a linear tetrahedron.
inline Mat3 deformation_gradient(const Vec12& x, const Mat3& Dm_inv) {
  return edge_matrix(x) * Dm_inv;
}

/// Cofactor matrix cof F = det(F) F⁻ᵀ, written with cross products so that it is defined
/// for singular F: columns (f2 × f3, f3 × f1, f1 × f2). It is ∂ det F / ∂F.
inline Mat3 cofactor(const Mat3& F) {
  Mat3 C;
  C.col(0) = F.col(1).cross(F.col(2));
  C.col(1) = F.col(2).cross(F.col(0));
  C.col(2) = F.col(0).cross(F.col(1));
  return C;
}

/// ∂C/∂x from ∂C/∂F: the gradient with respect to x_k (k = 1..3) is column k−1 of
/// (∂C/∂F) Dm⁻ᵀ, and the gradient with respect to x0 is minus their sum.
inline Vec12 gradient_from_dF(const Mat3& dCdF, const Mat3& Dm_inv) {
  const Mat3 G = dCdF * Dm_inv.transpose();
  Vec12 g;
  g << -G.rowwise().sum(), G.col(0), G.col(1), G.col(2);
  return g;
}

/// The weights b_k of particle k in F = Σ_k x_k b_kᵀ: row k−1 of Dm⁻¹ for k = 1..3, minus
/// their sum for k = 0. Moving x_k by δ changes F by δ b_kᵀ.
inline Vec3 stencil_weights(const Mat3& Dm_inv, int k) {
  return k == 0 ? Vec3(-Dm_inv.colwise().sum().transpose()) : Vec3(Dm_inv.row(k - 1).transpose());
}

/// ∂C/∂x_k = (∂C/∂F) b_k, one particle's part of gradient_from_dF.
inline Vec3 vertex_gradient(const Mat3& dCdF, const Vec3& b) { return dCdF * b; }

/// ∂vec(F)/∂x (9×12), constant for a linear tetrahedron.
Eigen::Matrix<double, 9, 12> dF_dx(const Mat3& Dm_inv);

/// ∂²C/∂x² = (∂F/∂x)ᵀ (∂²C/∂F²) (∂F/∂x), exact because F is linear in x.
Mat12 hessian_from_d2F(const Mat9& d2CdF2, const Mat3& Dm_inv);

/// ∂² det F / ∂vec(F)²: blocks of skew matrices of the columns of F.
Mat9 determinant_hessian(const Mat3& F);

}  // namespace rice::xpbd
