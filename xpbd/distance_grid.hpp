// A signed distance field sampled on a regular grid, for colliders of any shape (a bowl, a
// plate, a mould, a hand): values at grid points, read by trilinear interpolation, with the
// gradient of that interpolant as the normal. Built elsewhere (experiments/ turns a closed
// mesh into one with OpenVDB); xpbd only reads it. Points outside the grid read the nearest
// boundary value plus their distance to the grid, so far-away grains see no contact.
#pragma once

#include <vector>

#include "xpbd/types.hpp"

namespace rice::xpbd {

struct DistanceGrid {
  Vec3 origin = Vec3::Zero();              ///< position of grid point (0, 0, 0) [m]
  double spacing = 0.0;                    ///< distance between grid points [m]
  Eigen::Vector3i size = Eigen::Vector3i::Zero();  ///< grid points along x, y, z (each ≥ 2)
  std::vector<float> values;               ///< φ at point (i, j, k) = values[i + size.x (j + size.y k)]

  float at(int i, int j, int k) const { return values[i + size.x() * (j + size.y() * k)]; }
};

/// φ and ∇φ at p (trilinear; ∇φ normalised when not zero). Outside the grid, the value at the
/// nearest point inside plus the distance to it.
struct GridSample {
  double distance;
  Vec3 gradient;
};
GridSample sample(const DistanceGrid& grid, const Vec3& p);

/// Throws std::invalid_argument unless the grid has a positive finite spacing, at least two
/// points along each axis, one finite value per point and a finite origin.
void validate(const DistanceGrid& grid);

}  // namespace rice::xpbd
