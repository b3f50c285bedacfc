// Structured tetrahedral meshes and per-mesh quantities; see tet_mesh.hpp.
#include "xpbd/tet_mesh.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {

TetMesh make_box_tet_mesh(const Vec3& size, int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1 || !(size.minCoeff() > 0.0)) {
    throw std::invalid_argument("make_box_tet_mesh: need nx, ny, nz >= 1 and a positive size, got " +
                                std::to_string(nx) + "x" + std::to_string(ny) + "x" +
                                std::to_string(nz));
  }
  const auto index = [&](int i, int j, int k) { return box_vertex_index(nx, ny, i, j, k); };
  TetMesh mesh;
  mesh.V.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.V.row(index(i, j, k)) << size.x() * i / nx, size.y() * j / ny, size.z() * k / nz;

  // Six tetrahedra per cube: paths 0 → e_a → e_a + e_b → 7 over the permutations (a, b, c)
  // of the axes, corners numbered by bits (x, y, z).
  static constexpr std::array<std::array<int, 2>, 6> kPaths = {
      {{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}}};
  mesh.T.resize(6 * nx * ny * nz, 4);
  int t = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const auto corner = [&](int bits) {
          return index(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1));
        };
        for (const auto& [a, b] : kPaths) {
          int tet[4] = {corner(0), corner(1 << a), corner((1 << a) | (1 << b)), corner(7)};
          if (signed_volume(stack(mesh.V.row(tet[0]).transpose(), mesh.V.row(tet[1]).transpose(),
                                  mesh.V.row(tet[2]).transpose(),
                                  mesh.V.row(tet[3]).transpose())) < 0.0)
            std::swap(tet[2], tet[3]);
          mesh.T.row(t++) << tet[0], tet[1], tet[2], tet[3];
        }
      }
  return mesh;
}

std::vector<int> vertices_at_min_x(const Positions& V) {
  std::vector<int> indices;
  const double min_x = V.col(0).minCoeff();
  for (int i = 0; i < V.rows(); ++i)
    if (V(i, 0) == min_x) indices.push_back(i);
  return indices;
}

Eigen::VectorXd tet_volumes(const Positions& V, const Tets& T) {
  Eigen::VectorXd volumes(T.rows());
  for (int t = 0; t < T.rows(); ++t) volumes[t] = signed_volume(tet_positions(V, T, t));
  return volumes;
}

Eigen::VectorXd lumped_masses(const Positions& V, const Tets& T, double density) {
  Eigen::VectorXd masses = Eigen::VectorXd::Zero(V.rows());
  const Eigen::VectorXd volumes = tet_volumes(V, T);
  for (int t = 0; t < T.rows(); ++t)
    for (int c = 0; c < 4; ++c) masses[T(t, c)] += 0.25 * density * std::abs(volumes[t]);
  return masses;
}

}  // namespace rice::xpbd
