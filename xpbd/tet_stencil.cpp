// Chain rule from F to the particle coordinates of a tetrahedron; see tet_stencil.hpp.
#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {
namespace {

/// [a]× such that [a]× b = a × b.
Mat3 cross_matrix(const Vec3& a) {
  Mat3 S;
  S << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return S;
}

}  // namespace

Eigen::Matrix<double, 9, 12> dF_dx(const Mat3& Dm_inv) {
  // F(a, j) = Σ_k (x_k − x0)(a) Dm⁻¹(k−1, j)
  Eigen::Matrix<double, 9, 12> B = Eigen::Matrix<double, 9, 12>::Zero();
  for (int j = 0; j < 3; ++j) {
    const double column_sum = Dm_inv.col(j).sum();
    for (int a = 0; a < 3; ++a) {
      B(a + 3 * j, a) = -column_sum;
      for (int k = 1; k <= 3; ++k) B(a + 3 * j, 3 * k + a) = Dm_inv(k - 1, j);
    }
  }
  return B;
}

Mat12 hessian_from_d2F(const Mat9& d2CdF2, const Mat3& Dm_inv) {
  const Eigen::Matrix<double, 9, 12> B = dF_dx(Dm_inv);
  return B.transpose() * d2CdF2 * B;
}

Mat9 determinant_hessian(const Mat3& F) {
  // det F = f1 · (f2 × f3); block (i, j) is ∂(∂det/∂f_i)/∂f_j.
  const Mat3 S1 = cross_matrix(F.col(0));
  const Mat3 S2 = cross_matrix(F.col(1));
  const Mat3 S3 = cross_matrix(F.col(2));
  Mat9 H = Mat9::Zero();
  H.block<3, 3>(0, 3) = -S3;
  H.block<3, 3>(0, 6) = S2;
  H.block<3, 3>(3, 0) = S3;
  H.block<3, 3>(3, 6) = -S1;
  H.block<3, 3>(6, 0) = -S2;
  H.block<3, 3>(6, 3) = S1;
  return H;
}

}  // namespace rice::xpbd
