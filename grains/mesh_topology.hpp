// Topology checks for closed, manifold, consistently oriented triangle surfaces: what the
// level-set conversion and the tet mesher need from a user's base mesh, and what every
// render mesh must be.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "grains/mesh_types.hpp"

namespace rice::grains {

/// The first defect found that keeps `mesh` from being a closed, edge- and vertex-manifold,
/// consistently oriented surface, naming the face, edge or vertex; nullopt when there is
/// none. Checks, in order: indices in range and distinct per face; every undirected edge in
/// exactly two faces, used once in each direction; the faces around every vertex forming a
/// single fan. Vertices referenced by no face are allowed (they are ignored).
std::optional<std::string> closed_manifold_defect(const SurfaceMesh& mesh);

/// Throws std::invalid_argument "<source>: <defect>" when closed_manifold_defect finds one.
void require_closed_manifold(const SurfaceMesh& mesh, const std::string& source);

/// Number of connected components (by shared vertices) among the faces.
int connected_component_count(const SurfaceMesh& mesh);

/// A boundary face of a tet mesh (a face used by one tet), oriented outward for positively
/// oriented tets, and that tet.
struct BoundaryFace {
  Eigen::Vector3i corners;
  int tet;
};
std::vector<BoundaryFace> boundary_faces(const Tets& T);

/// The closed surface bounding a tet mesh: all its vertices, its boundary faces.
SurfaceMesh boundary_surface(const VolumeMesh& mesh);

}  // namespace rice::grains
