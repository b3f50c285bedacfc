// Normals and vertex values smoothed over a ball (smooth_normals.hpp).
#include "shading/smooth_normals.hpp"

#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

/// Area-weighted vertex normals, unnormalised: the sum of the faces' cross products (twice
/// the area times the unit normal), #V by 3.
MeshVertices area_weighted_normals(const MeshVertices& V, const MeshTriangles& F) {
  MeshVertices weighted = MeshVertices::Zero(V.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::RowVector3d n = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) weighted.row(F(f, k)) += n;
  }
  return weighted;
}

/// For each vertex v, visit(v, u, w) for every vertex u within `radius` of it that faces its
/// way (n_u · n_v > 0), w the Gaussian of standard deviation radius/2 in their distance; the
/// vertices v in parallel, so `visit` may write v's entries only.
template <class Visit>
void for_each_ball_neighbour(const MeshVertices& V, const MeshVertices& unit, double radius, Visit visit) {
  const auto key = [&](const Eigen::RowVector3d& p) {
    return CellKey{static_cast<long long>(std::floor(p.x() / radius)), static_cast<long long>(std::floor(p.y() / radius)),
                   static_cast<long long>(std::floor(p.z() / radius))};
  };
  std::unordered_map<CellKey, std::vector<int>, CellHash> grid;
  for (Eigen::Index v = 0; v < V.rows(); ++v) grid[key(V.row(v))].push_back(static_cast<int>(v));
  const double inverse_two_s2 = 1.0 / (2.0 * 0.25 * radius * radius);  // s = radius / 2
  // Each vertex's visits are its own (visit writes v's entries only): vertices in parallel.
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, V.rows(), 256), [&](const auto& range) {
    for (Eigen::Index v = range.begin(); v < range.end(); ++v) {
      const CellKey c = key(V.row(v));
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = -1; dz <= 1; ++dz) {
            const auto it = grid.find({c.x + dx, c.y + dy, c.z + dz});
            if (it == grid.end()) continue;
            for (const int u : it->second) {
              const double d2 = (V.row(u) - V.row(v)).squaredNorm();
              if (d2 > radius * radius || unit.row(u).dot(unit.row(v)) <= 0.0) continue;
              visit(static_cast<int>(v), u, std::exp(-d2 * inverse_two_s2));
            }
          }
    }
  });
}

void check_radius(double radius, const char* who) {
  if (!(radius >= 0.0)) throw std::invalid_argument(std::string(who) + ": the radius must be >= 0");
}

}  // namespace

MeshVertices smoothed_vertex_normals(const MeshVertices& V, const MeshTriangles& F, double radius) {
  check_radius(radius, "smoothed_vertex_normals");
  const MeshVertices unit = vertex_normals(V, F);
  if (radius == 0.0) return unit;
  const MeshVertices weighted = area_weighted_normals(V, F);
  MeshVertices sum = MeshVertices::Zero(V.rows(), 3);
  for_each_ball_neighbour(V, unit, radius, [&](int v, int u, double w) { sum.row(v) += w * weighted.row(u); });
  for (Eigen::Index v = 0; v < V.rows(); ++v) {
    const double norm = sum.row(v).norm();
    sum.row(v) = norm > 0.0 ? Eigen::RowVector3d(sum.row(v) / norm) : Eigen::RowVector3d(unit.row(v));
  }
  return sum;
}

Eigen::VectorXd smoothed_vertex_values(const MeshVertices& V, const MeshTriangles& F, const Eigen::VectorXd& values,
                                       double radius) {
  check_radius(radius, "smoothed_vertex_values");
  if (values.size() != V.rows())
    throw std::invalid_argument("smoothed_vertex_values: " + std::to_string(values.size()) + " values for " +
                                std::to_string(V.rows()) + " vertices");
  if (radius == 0.0) return values;
  const MeshVertices weighted = area_weighted_normals(V, F);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(V.rows()), weight = Eigen::VectorXd::Zero(V.rows());
  for_each_ball_neighbour(V, vertex_normals(V, F), radius, [&](int v, int u, double w) {
    const double a = w * weighted.row(u).norm();  // the Gaussian times u's share of the area
    sum(v) += a * values(u);
    weight(v) += a;
  });
  for (Eigen::Index v = 0; v < V.rows(); ++v) sum(v) = weight(v) > 0.0 ? sum(v) / weight(v) : values(v);
  return sum;
}

}  // namespace rice::shading
