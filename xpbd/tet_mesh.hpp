// Plain-matrix tetrahedral mesh utilities: a structured box mesh (for cantilevers, bars and
// columns), lumped masses, volumes. Meshes are (V, T) pairs as in
// types.hpp; nothing here knows about the solver.
#pragma once

#include <vector>

#include "xpbd/types.hpp"

namespace rice::xpbd {

struct TetMesh {
  Positions V;  ///< #V by 3 rest positions
  Tets T;       ///< #T by 4 positively oriented tetrahedra
};

/// Axis-aligned box [0, size] split into nx × ny × nz cubes, each cut into six tetrahedra
/// around its main diagonal (Kuhn/Freudenthal subdivision, conforming across faces).
/// Vertex (i, j, k) has index i + (nx+1) (j + (ny+1) k).
TetMesh make_box_tet_mesh(const Vec3& size, int nx, int ny, int nz);

/// Index of vertex (i, j, k) of make_box_tet_mesh(size, nx, ny, nz).
inline int box_vertex_index(int nx, int ny, int i, int j, int k) {
  return i + (nx + 1) * (j + (ny + 1) * k);
}

/// Vertices lying on the plane x = min x of the mesh (the clamped end of a cantilever).
std::vector<int> vertices_at_min_x(const Positions& V);

/// Positions of tetrahedron t as one 12-vector.
inline Vec12 tet_positions(const Positions& V, const Tets& T, int t) {
  return stack(V.row(T(t, 0)).transpose(), V.row(T(t, 1)).transpose(),
               V.row(T(t, 2)).transpose(), V.row(T(t, 3)).transpose());
}

/// Signed volume of every tetrahedron (#T).
Eigen::VectorXd tet_volumes(const Positions& V, const Tets& T);

/// Lumped masses: each vertex gets a quarter of ρ V_t of every tetrahedron around it (#V).
Eigen::VectorXd lumped_masses(const Positions& V, const Tets& T, double density);

}  // namespace rice::xpbd
