// Normals smoothed over a ball (smooth_normals.hpp).
#include "shading/smooth_normals.hpp"

#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace rice::shading {
namespace {

struct CellKey {
  long long x, y, z;
  bool operator==(const CellKey&) const = default;
};
struct CellHash {
  std::size_t operator()(const CellKey& k) const {
    return static_cast<std::size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
  }
};

}  // namespace

MeshVertices smoothed_vertex_normals(const MeshVertices& V, const MeshTriangles& F, double radius) {
  if (!(radius >= 0.0)) throw std::invalid_argument("smoothed_vertex_normals: the radius must be >= 0");
  // Area-weighted vertex normals, unnormalised: the sum of the faces' cross products.
  MeshVertices weighted = MeshVertices::Zero(V.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::RowVector3d n = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) weighted.row(F(f, k)) += n;
  }
  const MeshVertices unit = vertex_normals(V, F);
  if (radius == 0.0) return unit;
  const auto key = [&](const Eigen::RowVector3d& p) {
    return CellKey{static_cast<long long>(std::floor(p.x() / radius)), static_cast<long long>(std::floor(p.y() / radius)),
                   static_cast<long long>(std::floor(p.z() / radius))};
  };
  std::unordered_map<CellKey, std::vector<int>, CellHash> grid;
  for (Eigen::Index v = 0; v < V.rows(); ++v) grid[key(V.row(v))].push_back(static_cast<int>(v));
  const double inverse_two_s2 = 1.0 / (2.0 * 0.25 * radius * radius);  // s = radius / 2
  MeshVertices out(V.rows(), 3);
  for (Eigen::Index v = 0; v < V.rows(); ++v) {
    const CellKey c = key(V.row(v));
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({c.x + dx, c.y + dy, c.z + dz});
          if (it == grid.end()) continue;
          for (const int u : it->second) {
            const double d2 = (V.row(u) - V.row(v)).squaredNorm();
            if (d2 > radius * radius || unit.row(u).dot(unit.row(v)) <= 0.0) continue;
            sum += std::exp(-d2 * inverse_two_s2) * weighted.row(u);
          }
        }
    const double norm = sum.norm();
    out.row(v) = norm > 0.0 ? Eigen::RowVector3d(sum / norm) : Eigen::RowVector3d(unit.row(v));
  }
  return out;
}

}  // namespace rice::shading
