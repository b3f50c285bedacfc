// The box a render's default camera frames around a run's grains: the union of the grains'
// boxes, less strays. One grain thrown off the bunny's heap, 17 cm out, made the heap a speck in
// the corner of its preview.
#pragma once

#include <vector>

#include <Eigen/Geometry>

namespace rice::experiments {

/// The union of `grains` (one box each) whose centres lie, on every axis, within the 1st–99th
/// percentile of the centres widened by a tenth of that range and the largest grain's diagonal.
/// A pile's flank is kept; a grain far from the pile is not. Empty for no grains.
Eigen::AlignedBox3d framing_box(const std::vector<Eigen::AlignedBox3d>& grains);

}  // namespace rice::experiments
