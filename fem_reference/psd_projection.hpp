// Projection of a small symmetric matrix onto the positive semi-definite cone: eigenvalues
// clamped at zero (Teran et al. 2005, "Robust quasistatic finite elements and flesh
// simulation", §5). Applied per element so that the assembled Newton matrix is PSD even where
// the energy is not convex (compressed springs, inverted tets).
#pragma once

#include <Eigen/Eigenvalues>

namespace rice::fem {

template <int N>
Eigen::Matrix<double, N, N> project_to_psd(const Eigen::Matrix<double, N, N>& A) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(A);
  const auto& values = eigen.eigenvalues();
  if (values.minCoeff() >= 0.0) return A;
  const auto& vectors = eigen.eigenvectors();
  return vectors * values.cwiseMax(0.0).asDiagonal() * vectors.transpose();
}

}  // namespace rice::fem
