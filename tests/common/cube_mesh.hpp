// A closed cube mesh for the tests of meshes, moulds and sections.
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::test_support {

/// A closed cube of `side` [m] about the origin, faces outward.
inline grains::SurfaceMesh cube(double side) {
  grains::SurfaceMesh mesh;
  mesh.V.resize(8, 3);
  for (int k = 0; k < 8; ++k)
    mesh.V.row(k) = 0.5 * side * Eigen::RowVector3d((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
  mesh.F.resize(12, 3);
  mesh.F << 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5;
  return mesh;
}

}  // namespace rice::test_support
