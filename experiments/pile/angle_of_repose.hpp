// The angle of repose of a heap of grains on a flat floor, from the grains' centres: the
// heap's axis passes through the median centre in x and y; the ground ring of width `ring_width` at
// distance r from the axis is as high as its highest centre; the angle is the slope of the
// least-squares line through the rings whose heights lie between 15% and 85% of the apex
// above the lowest centre, which leaves out the rounded apex and the toe of single grains
// rolled away (the usual reading of a heap's flank, e.g. Zhou et al. 2002, "Rolling friction
// in the dynamic simulation of sandpile formation", Physica A 269).
#pragma once

#include <vector>

#include "xpbd/types.hpp"

namespace rice::experiments {

struct HeapProfile {
  std::vector<double> ring_radius;  ///< [m] the radius of each ring's highest centre
  std::vector<double> ring_height;  ///< [m] above the lowest centre
  std::vector<bool> on_flank;       ///< used by the fit
  double apex_height = 0.0;         ///< [m] above the lowest centre
  double slope = 0.0, intercept = 0.0;  ///< height ≈ intercept + slope · radius on the flank
  double angle_degrees = 0.0;       ///< atan(−slope)
};

/// Throws std::invalid_argument when fewer than two rings lie on the flank (too few grains or
/// too wide rings) or `ring_width` is not positive.
HeapProfile heap_profile(const std::vector<xpbd::Vec3>& centres, double ring_width);

}  // namespace rice::experiments
