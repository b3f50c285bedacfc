// The Hessian of the strain-rate damping potential; see strain_rate_damping.hpp.
#include "xpbd/strain_rate_damping.hpp"

namespace rice::xpbd {

Mat9 strain_rate_damping_d2F(const Mat3& F_start, double mu, double lambda_lame) {
  // ∂φ/∂ΔF is linear in ΔF, so its value at each unit ΔF is a column of the Hessian.
  Mat9 H;
  for (int q = 0; q < 9; ++q) {
    Mat3 unit = Mat3::Zero();
    unit(q % 3, q / 3) = 1.0;
    const Mat3 column = strain_rate_damping_dF(F_start, unit, mu, lambda_lame);
    H.col(q) = Eigen::Map<const Vec9>(column.data());
  }
  return H;
}

}  // namespace rice::xpbd
