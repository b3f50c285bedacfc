// A closed triangle mesh with fewer vertices: CGAL's edge-collapse simplification
// (Surface_mesh_simplification, Lindstrom–Turk cost and placement) until at most a given
// number of vertices remain. For exports that carry every grain of a run in every frame
// (`rice point-cache`): a render mesh's 20,000 vertices times 800 grains times 180 frames is
// 35 GB of positions.
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::grains {

/// `mesh` simplified to at most `max_vertices` vertices (≥ 4); the mesh itself when it has
/// no more. A mesh of many parts (a porous grain's pores) keeps each part, so it may stop
/// above max_vertices when the parts cannot shrink further. Throws std::invalid_argument for
/// max_vertices < 4 or a mesh CGAL cannot read as a closed manifold.
SurfaceMesh simplified(const SurfaceMesh& mesh, int max_vertices);

}  // namespace rice::grains
