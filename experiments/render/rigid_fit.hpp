// The rigid motion that best carries a soft grain's rest simulation vertices onto its deformed
// ones, in the least-squares sense (Umeyama's method, Eigen::umeyama), its scale held at the
// grain's swell P. A soft grain that close to rigid is drawn as an instance of its variant
// (run_frames.hpp), sharing the variant's hierarchy as a rigid grain does, instead of as a
// mesh of its own.
#pragma once

#include <Eigen/Geometry>

#include "grains/mesh_types.hpp"

namespace rice::experiments {

struct RigidFit {
  Eigen::Affine3d place;  ///< x ≈ place · rest: a rotation, the scale P and a translation
  double residual = 0.0;  ///< max over the vertices of |place · rest_k − x_k| [m]
};

/// The fit of `x` (#V×3, deformed) by `rest` (#V×3, the variant's simulation vertices at
/// scale 1) scaled by `swell`. Throws std::invalid_argument when the sizes differ.
RigidFit fit_rigid_motion(const grains::Vertices& rest, double swell, const grains::Vertices& x);

}  // namespace rice::experiments
