// Tetrahedron volume constraint C(x) = V(x) − V0 with V(x) = det(Ds) / 6
// (Müller et al. 2007, "Position Based Dynamics", §4; XPBD's volume test), with gradient and
// Hessian. V(x) is det of the edge matrix, so the derivatives reuse the stencil calculus
// with Dm⁻¹ = I.
#pragma once

#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {

/// C = det(Ds) / 6 − V0.
inline double tet_volume_constraint_value(const Vec12& x, double rest_volume) {
  return signed_volume(x) - rest_volume;
}

/// ∇C: columns of cof(Ds) / 6 for x1..x3, minus their sum for x0.
inline Vec12 tet_volume_constraint_gradient(const Vec12& x) {
  return gradient_from_dF(cofactor(edge_matrix(x)) / 6.0, Mat3::Identity());
}

/// ∇²C from the Hessian of the determinant.
inline Mat12 tet_volume_constraint_hessian(const Vec12& x) {
  return hessian_from_d2F(determinant_hessian(edge_matrix(x)) / 6.0, Mat3::Identity());
}

}  // namespace rice::xpbd
