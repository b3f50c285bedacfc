// Two unit vectors completing a unit vector w to a right-handed orthonormal frame (t, s, w),
// for sampling directions around a normal, a light's axis or a travel direction.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <utility>

namespace rice::shading {

/// (t, s) with t ⟂ w, s = w × t; w unit, float or double.
template <class Vector>
std::pair<Vector, Vector> tangent_frame(const Vector& w) {
  using Scalar = typename Vector::Scalar;
  const Vector t = (std::abs(w.x()) < Scalar(0.9) ? Vector::UnitX() : Vector::UnitY()).cross(w).normalized();
  return {t, w.cross(t)};
}

}  // namespace rice::shading
