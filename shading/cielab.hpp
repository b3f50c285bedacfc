// CIELAB of linear sRGB colours and the CIE76 colour difference ΔE*ab, to say how visibly two
// renders differ (the soaks of Figure 13). sRGB primaries and D65 white (IEC 61966-2-1), the
// white (1, 1, 1) at L* = 100; CIE 15:2004's L*a*b* with its linear segment near black.
// Written by hand: a few lines, and no colour library is among our dependencies.
#pragma once

#include <Eigen/Dense>

#include <cmath>

namespace rice::shading {

/// L*, a*, b* of a linear sRGB colour (1 = the white).
inline Eigen::Vector3d cielab(const Eigen::Vector3d& linear_srgb) {
  Eigen::Matrix3d to_xyz;
  to_xyz << 0.4124564, 0.3575761, 0.1804375,  //
      0.2126729, 0.7151522, 0.0721750,         //
      0.0193339, 0.1191920, 0.9503041;
  const Eigen::Vector3d white = to_xyz * Eigen::Vector3d::Ones();
  const Eigen::Vector3d t = (to_xyz * linear_srgb).cwiseQuotient(white);
  const auto f = [](double v) {
    constexpr double delta = 6.0 / 29.0;
    return v > delta * delta * delta ? std::cbrt(v) : v / (3.0 * delta * delta) + 4.0 / 29.0;
  };
  const double fx = f(t.x()), fy = f(t.y()), fz = f(t.z());
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

/// CIE76 ΔE*ab: the distance of two colours in L*a*b*.
inline double delta_e76(const Eigen::Vector3d& linear_a, const Eigen::Vector3d& linear_b) {
  return (cielab(linear_a) - cielab(linear_b)).norm();
}

}  // namespace rice::shading
