// Constraint values and derivatives in reduced coordinates; see constraint_kernels.hpp.
#include "fem_reference/constraint_kernels.hpp"

namespace rice::fem {

NeoHookeanKernel::Derivatives NeoHookeanKernel::evaluate(const Constraint& c, const Vec9& y, Order order) {
  const Eigen::Map<const Mat3> F(y.data());
  const xpbd::TetConstraintPair p = xpbd::tet_constraint_pair(c, F);
  Derivatives d;
  d.C = p.C;
  if (order == Order::kValue) return d;
  d.dC.row(0) = Eigen::Map<const Vec9>(p.dD.data()).transpose();
  d.dC.row(1) = Eigen::Map<const Vec9>(p.dH.data()).transpose();
  if (order == Order::kGradient) return d;
  d.d2C[0] = xpbd::tet_deviatoric_d2F(c, F);
  d.d2C[1] = xpbd::determinant_hessian(F);
  return d;
}

TetVolumeKernel::Derivatives TetVolumeKernel::evaluate(const Constraint& c, const Vec9& y, Order order) {
  // V = det(Ds)/6: the xpbd volume kernel's math with F = Ds (tet_volume_constraint.hpp).
  const Eigen::Map<const Mat3> Ds(y.data());
  Derivatives d;
  d.C[0] = Ds.determinant() / 6.0 - c.rest_volume;
  if (order == Order::kValue) return d;
  const Mat3 cof = xpbd::cofactor(Ds) / 6.0;
  d.dC = Eigen::Map<const Vec9>(cof.data()).transpose();
  if (order == Order::kGradient) return d;
  d.d2C[0] = xpbd::determinant_hessian(Ds) / 6.0;
  return d;
}

DistanceKernel::Derivatives DistanceKernel::evaluate(const Constraint& c, const Vec3& y, Order order) {
  // The xpbd spring kernels with x0 = y, x1 = 0.
  const Vec3 origin = Vec3::Zero();
  Derivatives d;
  d.C[0] = xpbd::distance_constraint_value(y, origin, c.rest_length);
  if (order == Order::kValue) return d;
  d.dC = xpbd::distance_constraint_gradient(y, origin).head<3>().transpose();
  if (order == Order::kGradient) return d;
  d.d2C[0] = xpbd::distance_constraint_hessian(y, origin).topLeftCorner<3, 3>();
  return d;
}

AttachmentKernel::Derivatives AttachmentKernel::evaluate(const Constraint& c, const Vec3& y, Order order) {
  Derivatives d;
  d.C = y - c.target;
  if (order == Order::kValue) return d;
  d.dC.setIdentity();
  if (order == Order::kGradient) return d;
  for (auto& H : d.d2C) H.setZero();
  return d;
}

}  // namespace rice::fem
