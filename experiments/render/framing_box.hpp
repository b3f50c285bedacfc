// What a render's default camera frames, and the camera that frames it. The box is the union
// of the grains' boxes, less strays: one grain thrown off the bunny's heap, 17 cm out, made the
// heap a speck in the corner of its preview. The camera fits the box's eight corners to the
// image, so a row of grains fills the width instead of a sphere around it.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "shading/camera.hpp"

namespace rice::experiments {

/// The union of `grains` (one box each) whose centres lie, on every axis, within the 1st–99th
/// percentile of the centres widened by a tenth of that range and the largest grain's diagonal.
/// A pile's flank is kept; a grain far from the pile is not. Empty for no grains.
Eigen::AlignedBox3d framing_box(const std::vector<Eigen::AlignedBox3d>& grains);

/// A pinhole camera looking from the given elevation and azimuth [degrees] (from +x towards
/// +y) at `bounds`, its distance the least at which all eight corners lie in an image of
/// width/height `aspect`, with a 5% margin, and its target centring their projections.
shading::Camera framing_camera(const Eigen::AlignedBox3d& bounds, double elevation_degrees, double azimuth_degrees,
                               double vertical_fov_degrees, double aspect);

}  // namespace rice::experiments
