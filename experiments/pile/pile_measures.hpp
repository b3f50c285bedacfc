// What a pile of grains looks like, for the drop scenes (paper Fig. 10: wetter grains clump
// and stay heaped, drier ones scatter) and the sections of filled moulds: the radius of its
// footprint from above, the number of groups of grains that touch, and its top.
#pragma once

#include <vector>

#include "xpbd/model.hpp"

namespace rice::experiments {

/// The radius about the mean of `centres` (in the horizontal plane) within which `fraction`
/// of them lie [m]; 0 for no centres.
double footprint_radius(const std::vector<xpbd::Vec3>& centres, double fraction = 0.9);

/// The pile's top [m]: the height under which `fraction` of `centres` lie, so that a few
/// grains lifted above the pile (a paddle's portion) do not set it; NaN for no centres.
double pile_top(const std::vector<xpbd::Vec3>& centres, double fraction = 0.95);

/// The number of groups of bodies that touch: two bodies whose collision spheres come within
/// `gap` [m] of each other are in one group, and so are their groups (union–find).
int count_clusters(const xpbd::Model& model, double gap);

}  // namespace rice::experiments
