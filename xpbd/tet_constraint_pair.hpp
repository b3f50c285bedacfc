// The elastic pair (C_D, C_H) of a tet and its derivatives in F, for either material
// (NeoHookeanTet::material): the one place that tells the materials apart, so that XPBD,
// vertex block descent, the energy and the reference solver read the same constraints.
#pragma once

#include "xpbd/corotated_constraints.hpp"
#include "xpbd/model.hpp"
#include "xpbd/neo_hookean_constraints.hpp"

namespace rice::xpbd {

struct TetConstraintPair {
  Vec2 C;       ///< (C_D, C_H)
  Mat3 dD, dH;  ///< ∂C_D/∂F, ∂C_H/∂F
};

/// The pair at F; `R` is F's polar rotation, read by the corotated material only (XPBD
/// passes its warm-started one).
inline TetConstraintPair tet_constraint_pair(const NeoHookeanTet& t, const Mat3& F, const Mat3& R) {
  TetConstraintPair p;
  if (t.corotated()) {
    p.C[0] = corotated_deviatoric_value(F, R);
    p.dD = corotated_deviatoric_dF(F, R);
  } else {
    p.C[0] = neo_hookean_deviatoric_value(F);
    p.dD = neo_hookean_deviatoric_dF(F);
  }
  p.C[1] = F.determinant() - t.rest_determinant();
  p.dH = cofactor(F);  // ∂ det F/∂F for both
  return p;
}

/// The rotation tet_constraint_pair needs: the polar one for a corotated tet, else unused.
inline Mat3 tet_rotation(const NeoHookeanTet& t, const Mat3& F) {
  return t.corotated() ? polar_rotation(F) : Mat3::Identity();
}

inline TetConstraintPair tet_constraint_pair(const NeoHookeanTet& t, const Mat3& F) {
  return tet_constraint_pair(t, F, tet_rotation(t, F));
}

/// ∂²C_D/∂F²; ∂²C_H/∂F² is determinant_hessian(F) for both materials.
inline Mat9 tet_deviatoric_d2F(const NeoHookeanTet& t, const Mat3& F) {
  return t.corotated() ? corotated_deviatoric_d2F(F) : neo_hookean_deviatoric_d2F(F);
}

}  // namespace rice::xpbd
