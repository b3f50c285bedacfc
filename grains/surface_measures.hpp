// Measures of closed triangle surfaces: enclosed volume, area, bounding box.
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::grains {

/// Enclosed volume by the divergence theorem, V = Σ_f (a·(b×c))/6; positive when the faces
/// are oriented outwards. Interior cavities (inward-facing shells) count negatively.
double enclosed_volume(const SurfaceMesh& mesh);

/// Total triangle area.
double surface_area(const SurfaceMesh& mesh);

/// Side lengths of the axis-aligned bounding box of the vertices.
Vec3 bounding_box_extent(const Vertices& V);

/// Reverses every face (flips the orientation of the surface).
void flip_orientation(SurfaceMesh& mesh);

}  // namespace rice::grains
