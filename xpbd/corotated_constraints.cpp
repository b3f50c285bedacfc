// Polar rotation and its derivative for the corotated pair; see corotated_constraints.hpp.
#include "xpbd/corotated_constraints.hpp"

#include <Eigen/SVD>
#include <cmath>

namespace rice::xpbd {
namespace {

/// F = U Σ Vᵀ with U, V rotations: a reflection moves into the smallest singular value,
/// which turns negative for an inverted F.
struct RotationVariantSvd {
  Mat3 U, V;
  Vec3 sigma;
};

RotationVariantSvd rotation_variant_svd(const Mat3& F) {
  const Eigen::JacobiSVD<Mat3> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  RotationVariantSvd s{svd.matrixU(), svd.matrixV(), svd.singularValues()};
  if (s.U.determinant() < 0.0) {
    s.U.col(2) *= -1.0;
    s.sigma[2] *= -1.0;
  }
  if (s.V.determinant() < 0.0) {
    s.V.col(2) *= -1.0;
    s.sigma[2] *= -1.0;
  }
  return s;
}

}  // namespace

Mat3 polar_rotation(const Mat3& F) {
  const RotationVariantSvd s = rotation_variant_svd(F);
  return s.U * s.V.transpose();
}

void refine_polar_rotation(const Mat3& F, Eigen::Quaterniond& q, int max_iterations) {
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    const Mat3 R = q.toRotationMatrix();
    // Rotating R to exp([ω]) R changes tr(RᵀF) by τ·ω − ½ ωᵀ H ω with B = F Rᵀ.
    const Vec3 torque = R.col(0).cross(F.col(0)) + R.col(1).cross(F.col(1)) + R.col(2).cross(F.col(2));
    const Mat3 B = F * R.transpose();
    const Mat3 H = B.trace() * Mat3::Identity() - 0.5 * (B + B.transpose());
    // H is positive definite when its leading minors are (Sylvester); then ω = adj(H) τ / det H.
    const double minor2 = H(0, 0) * H(1, 1) - H(0, 1) * H(0, 1), det = H.determinant();
    const Vec3 omega = H(0, 0) > 0.0 && minor2 > 0.0 && det > 0.0 ? Vec3(cofactor(H) * torque / det)
                                                                    : Vec3(torque / (std::abs(B.trace()) + 1e-9));
    if (omega.squaredNorm() < 1e-24) break;
    // exp([ω]) to second order, the quaternion (1, ω/2) normalised: the same fixed point, and
    // no trigonometry.
    q = (Eigen::Quaterniond(1.0, 0.5 * omega.x(), 0.5 * omega.y(), 0.5 * omega.z()) * q).normalized();
  }
}

Mat9 polar_rotation_dF(const Mat3& F) {
  const RotationVariantSvd s = rotation_variant_svd(F);
  // Twist i turns about axis i: T_0 mixes (1, 2), T_1 (0, 2), T_2 (0, 1).
  constexpr int kPairs[3][2] = {{1, 2}, {0, 2}, {0, 1}};
  Mat9 dR = Mat9::Zero();
  for (const auto& [j, k] : kPairs) {
    const double sum = s.sigma[j] + s.sigma[k];
    if (std::abs(sum) < 1e-12) continue;  // R jumps here: no derivative
    Mat3 T = Mat3::Zero();
    T(j, k) = -1.0 / std::sqrt(2.0);
    T(k, j) = 1.0 / std::sqrt(2.0);
    const Mat3 twist = s.U * T * s.V.transpose();
    const Eigen::Map<const Vec9> t(twist.data());
    dR += 2.0 / sum * t * t.transpose();
  }
  return dR;
}

Mat9 corotated_deviatoric_d2F(const Mat3& F) {
  const Mat3 D = F - polar_rotation(F);
  const double C = D.norm();
  if (!(C > 0.0)) return Mat9::Zero();
  const Eigen::Map<const Vec9> g(D.data());
  return (Mat9::Identity() - polar_rotation_dF(F) - g * g.transpose() / (C * C)) / C;
}

}  // namespace rice::xpbd
