// A planar slice through a grain's level set (paper Fig. 7): signed distances sampled on a
// regular grid, for images and for checking the porous structure by eye.
#pragma once

#include <openvdb/openvdb.h>

#include "grains/mesh_types.hpp"

namespace rice::grains {

/// Signed distance [m] on the plane z = `z` over the rectangle [low, high] (x, y), sampled
/// at `pixel` spacing; row i is y = high.y − (i + ½) pixel (top row first, as in an image),
/// column j is x = low.x + (j + ½) pixel. Outside the narrow band the grid's background.
Eigen::MatrixXf cross_section_z(const openvdb::FloatGrid& grid, const Vec3& low, const Vec3& high, double z,
                                double pixel);

}  // namespace rice::grains
