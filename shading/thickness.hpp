// A closed, possibly porous mesh's local thickness at each vertex: the distance from the
// vertex, inwards along its normal, to where that line leaves the body for good (through any
// pores on the way). It drives the translucent rice model's light through the grain
// (translucency.hpp): a thin edge lets through light that a thick middle does not. And which
// vertices lie on the outer surface, not on the wall of a pore inside. Rays cast on the mesh
// alone (Embree, through a RenderScene of that one mesh).
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "shading/curvature.hpp"

namespace rice::shading {

/// Thickness d ≥ 0 at every vertex (#V), in the mesh's units, along −N with N the
/// area-weighted vertex normal. A vertex whose inward ray meets nothing (an open mesh) gets 0.
/// Throws std::invalid_argument for an empty mesh or bad indices.
Eigen::VectorXd vertex_thickness(const MeshVertices& V, const MeshTriangles& F);

/// Whether each vertex sees out: its ray along +N meets nothing of the mesh. False on the
/// walls of closed pores (and at the bottom of dents deep enough to hide the sky overhead).
std::vector<bool> vertex_sees_out(const MeshVertices& V, const MeshTriangles& F);

}  // namespace rice::shading
