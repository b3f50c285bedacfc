// Turns a closed triangle mesh (a bowl, a plate, a mould, a hand) into the sampled signed
// distance field an xpbd collider reads: OpenVDB's mesh-to-SDF (grains/porous_level_set.hpp),
// copied onto a dense grid over the mesh's box and a margin.
#pragma once

#include "grains/mesh_types.hpp"
#include "xpbd/distance_grid.hpp"

namespace rice::experiments {

/// φ of `mesh` on grid points `spacing` apart covering its bounding box grown by `margin`
/// (filled inside; beyond OpenVDB's band of 3 voxels outside, φ reads 3 voxels). `hollow`:
/// −φ, the solid outside the mesh and the room inside it (a mould holding grains). Throws
/// std::invalid_argument for a spacing that is not positive or a grid over 2^28 points.
xpbd::DistanceGrid distance_grid_of(const grains::SurfaceMesh& mesh, double spacing, double margin,
                                    bool hollow = false);

}  // namespace rice::experiments
