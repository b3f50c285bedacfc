// An irregular tet mesh for tests: a structured box mesh whose interior vertices are moved
// by a seeded random fraction of a cell, so that no two tets have the same shape.
#pragma once

#include <random>

#include "xpbd/tet_mesh.hpp"

namespace rice::test_support {

/// make_box_tet_mesh(size, nx, ny, nz) with interior vertices displaced uniformly by up to
/// `jitter` cells along each axis (jitter < 0.25 keeps every tet positively oriented).
inline xpbd::TetMesh jittered_box_mesh(const xpbd::Vec3& size, int nx, int ny, int nz,
                                       double jitter, unsigned seed = 1) {
  xpbd::TetMesh mesh = xpbd::make_box_tet_mesh(size, nx, ny, nz);
  const xpbd::Vec3 cell = size.cwiseQuotient(xpbd::Vec3(nx, ny, nz));
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  for (int i = 1; i < nx; ++i)
    for (int j = 1; j < ny; ++j)
      for (int k = 1; k < nz; ++k) {
        const int v = xpbd::box_vertex_index(nx, ny, i, j, k);
        for (int a = 0; a < 3; ++a) mesh.V(v, a) += offset(random) * cell[a];
      }
  return mesh;
}

}  // namespace rice::test_support
