// A mesh's vertices split along its creases; see crease_split.hpp.
#include "experiments/render/crease_split.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace rice::experiments {

grains::SurfaceMesh split_creases(const grains::SurfaceMesh& mesh, double angle_degrees) {
  const double cos_angle = std::cos(angle_degrees * std::numbers::pi / 180.0);
  const Eigen::Index faces = mesh.F.rows();
  std::vector<Eigen::Vector3d> normal(static_cast<std::size_t>(faces));
  std::vector<std::vector<int>> faces_at(static_cast<std::size_t>(mesh.V.rows()));
  for (Eigen::Index f = 0; f < faces; ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    normal[f] = (b - a).cross(c - a).normalized();
    for (int k = 0; k < 3; ++k) faces_at[mesh.F(f, k)].push_back(static_cast<int>(f));
  }
  grains::SurfaceMesh out{grains::Vertices(0, 3), mesh.F};
  std::vector<Eigen::RowVector3d> vertices;
  for (std::size_t v = 0; v < faces_at.size(); ++v) {
    std::vector<int> seeds;  // each group's first face; the group's vertex is vertices[first + g]
    const int first = static_cast<int>(vertices.size());
    for (const int f : faces_at[v]) {
      std::size_t g = 0;
      while (g < seeds.size() && normal[f].dot(normal[seeds[g]]) < cos_angle) ++g;
      if (g == seeds.size()) {
        seeds.push_back(f);
        vertices.push_back(mesh.V.row(static_cast<Eigen::Index>(v)));
      }
      for (int k = 0; k < 3; ++k)
        if (mesh.F(f, k) == static_cast<int>(v)) out.F(f, k) = first + static_cast<int>(g);
    }
  }
  out.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t i = 0; i < vertices.size(); ++i) out.V.row(static_cast<Eigen::Index>(i)) = vertices[i];
  return out;
}

}  // namespace rice::experiments
