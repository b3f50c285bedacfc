// Re-polygonisation of a grain's level set (paper §4.1, "re-polygonalized by the level set
// method"): OpenVDB's volumeToMesh, quads split into triangles, faces oriented outwards.
#pragma once

#include <openvdb/openvdb.h>

#include "grains/mesh_types.hpp"

namespace rice::grains {

/// The zero iso-surface of `grid` as a closed triangle mesh. `adaptivity` in [0, 1] lets
/// volumeToMesh merge voxels in flat regions (0: uniform, one vertex per surface voxel).
SurfaceMesh level_set_to_mesh(const openvdb::FloatGrid& grid, double adaptivity);

}  // namespace rice::grains
