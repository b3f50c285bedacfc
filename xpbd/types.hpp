// Eigen types shared by the XPBD solver and the reference solver. Geometry crosses module
// boundaries as plain matrices (DESIGN.md): V is #V by 3 (one vertex a row), T is #T by 4
// (one tetrahedron a row, positively oriented).
#pragma once

#include <Eigen/Dense>

namespace rice::xpbd {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

/// #V by 3 positions (or velocities, forces), one particle a row. Row-major so that one
/// particle's three coordinates are contiguous in memory.
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #T by 4 vertex indices of tetrahedra.
using Tets = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;

/// Particle i's row of a Positions matrix as a 3-vector view.
inline Eigen::Map<Vec3> position(Positions& x, int i) { return Eigen::Map<Vec3>(x.data() + 3 * i); }
inline Eigen::Map<const Vec3> position(const Positions& x, int i) {
  return Eigen::Map<const Vec3>(x.data() + 3 * i);
}

/// Stacks four particle positions into one 12-vector (the stencil of a tetrahedron).
inline Vec12 stack(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  Vec12 x;
  x << x0, x1, x2, x3;
  return x;
}

}  // namespace rice::xpbd
