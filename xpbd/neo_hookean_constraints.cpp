// Second derivative of the deviatoric Neo-Hookean constraint; see neo_hookean_constraints.hpp.
#include "xpbd/neo_hookean_constraints.hpp"

namespace rice::xpbd {

Mat9 neo_hookean_deviatoric_d2F(const Mat3& F) {
  const double norm = F.norm();
  if (norm <= 0.0) return Mat9::Zero();
  const Eigen::Map<const Vec9> f(F.data());
  return (Mat9::Identity() - f * f.transpose() / (norm * norm)) / norm;
}

}  // namespace rice::xpbd
