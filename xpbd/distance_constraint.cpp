// Hessian of the distance constraint; see distance_constraint.hpp.
#include "xpbd/distance_constraint.hpp"

namespace rice::xpbd {

Mat6 distance_constraint_hessian(const Vec3& x0, const Vec3& x1) {
  const Vec3 d = x0 - x1;
  const double length = d.norm();
  Mat6 H = Mat6::Zero();
  if (length <= kCoincidentDistance) return H;
  const Vec3 n = d / length;
  const Mat3 K = (Mat3::Identity() - n * n.transpose()) / length;
  H.block<3, 3>(0, 0) = K;
  H.block<3, 3>(0, 3) = -K;
  H.block<3, 3>(3, 0) = -K;
  H.block<3, 3>(3, 3) = K;
  return H;
}

}  // namespace rice::xpbd
