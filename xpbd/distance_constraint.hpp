// Distance (spring) constraint between two particles, C(x0, x1) = |x0 − x1| − L
// (Müller et al. 2007, "Position Based Dynamics", §3.3), with its gradient and Hessian.
// Stateless kernels: the solver owns the multipliers.
#pragma once

#include "xpbd/types.hpp"

namespace rice::xpbd {

/// Below this separation the direction x0 − x1 is undefined and the gradient is taken as 0.
inline constexpr double kCoincidentDistance = 1e-14;

/// C = |x0 − x1| − L.
inline double distance_constraint_value(const Vec3& x0, const Vec3& x1, double rest_length) {
  return (x0 - x1).norm() - rest_length;
}

/// ∇C = [n, −n] with n = (x0 − x1) / |x0 − x1|; zero for coincident particles.
inline Vec6 distance_constraint_gradient(const Vec3& x0, const Vec3& x1) {
  const Vec3 d = x0 - x1;
  const double length = d.norm();
  Vec6 g = Vec6::Zero();
  if (length > kCoincidentDistance) {
    g.head<3>() = d / length;
    g.tail<3>() = -d / length;
  }
  return g;
}

/// ∇²C = [K, −K; −K, K] with K = (I − n nᵀ) / |x0 − x1|; zero for coincident particles.
Mat6 distance_constraint_hessian(const Vec3& x0, const Vec3& x1);

}  // namespace rice::xpbd
