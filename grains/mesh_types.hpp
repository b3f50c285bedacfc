// Plain-matrix meshes of the grains module. Geometry leaves this module as Eigen matrices
// (DESIGN.md): V is #V by 3 vertices, F is #F by 3 triangles (counter-clockwise seen from
// outside), T is #T by 4 positively oriented tetrahedra. The layouts equal those of
// rice::xpbd (row-major, one vertex a row), so a grain hands over without copying.
#pragma once

#include <Eigen/Dense>

#include <array>

namespace rice::grains {

using Vec3 = Eigen::Vector3d;
/// #V by 3 vertex positions, one vertex a row.
using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #F by 3 vertex indices of triangles.
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #T by 4 vertex indices of tetrahedra.
using Tets = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;

/// A triangle surface: vertices and faces.
struct SurfaceMesh {
  Vertices V;
  Triangles F;
};

/// A tetrahedral volume mesh: vertices and tetrahedra.
struct VolumeMesh {
  Vertices V;
  Tets T;
};

/// Corner positions of triangle f.
inline std::array<Vec3, 3> triangle_corners(const SurfaceMesh& mesh, Eigen::Index f) {
  return {mesh.V.row(mesh.F(f, 0)).transpose(), mesh.V.row(mesh.F(f, 1)).transpose(),
          mesh.V.row(mesh.F(f, 2)).transpose()};
}

/// Corner positions of tetrahedron t.
inline std::array<Vec3, 4> tet_corners(const VolumeMesh& mesh, Eigen::Index t) {
  return {mesh.V.row(mesh.T(t, 0)).transpose(), mesh.V.row(mesh.T(t, 1)).transpose(),
          mesh.V.row(mesh.T(t, 2)).transpose(), mesh.V.row(mesh.T(t, 3)).transpose()};
}

}  // namespace rice::grains
