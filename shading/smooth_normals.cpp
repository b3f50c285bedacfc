// Normals and vertex values smoothed over a ball (smooth_normals.hpp).
#include "shading/smooth_normals.hpp"

#include <algorithm>
#include <array>
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

/// The vertices bucketed by cells of side `radius`: cell c's vertices are order[begin[c],
/// begin[c + 1]) in index order, their positions and unit normals packed beside them so that
/// a cell's neighbourhood is read from contiguous memory (a render of a run, set up mostly
/// by this smoothing, went from 14.1 to 11.0 s with the same image; the candidates, not memory
/// access, are the rest of its cost).
struct CellBuckets {
  std::vector<CellKey> keys;  ///< cell c's key
  std::unordered_map<CellKey, int, CellHash> cell;
  std::vector<int> begin, order;
  std::vector<Eigen::Vector3d> position, normal;  ///< of order[s]
};

CellBuckets bucket_vertices(const MeshVertices& V, const MeshVertices& unit, double radius) {
  CellBuckets b;
  std::vector<int> cell_of(V.rows());
  for (Eigen::Index v = 0; v < V.rows(); ++v) {
    const CellKey key{static_cast<long long>(std::floor(V(v, 0) / radius)),
                      static_cast<long long>(std::floor(V(v, 1) / radius)),
                      static_cast<long long>(std::floor(V(v, 2) / radius))};
    const auto [it, added] = b.cell.try_emplace(key, static_cast<int>(b.keys.size()));
    if (added) b.keys.push_back(key);
    cell_of[v] = it->second;
  }
  b.begin.assign(b.keys.size() + 1, 0);  // a counting sort, stable: index order within a cell
  for (const int c : cell_of) ++b.begin[c + 1];
  for (size_t c = 0; c < b.keys.size(); ++c) b.begin[c + 1] += b.begin[c];
  std::vector<int> next(b.begin.begin(), b.begin.end() - 1);
  b.order.resize(V.rows());
  for (Eigen::Index v = 0; v < V.rows(); ++v) b.order[next[cell_of[v]]++] = static_cast<int>(v);
  for (const int v : b.order) {
    b.position.emplace_back(V.row(v).transpose());
    b.normal.emplace_back(unit.row(v).transpose());
  }
  return b;
}

/// exp(−2t) for t = d²/radius² in [0, 1] (the Gaussian of standard deviation radius/2), read
/// linearly from 4097 nodes: within 3e-8 of it, and cheaper than std::exp in the loop below
/// (a 17,800-vertex grain's normals at the renderer's 1.2 mm took 674 ms by std::exp, 505 ms
/// so; bench_render_setup). Rejected: clustering the vertices so that a Gaussian serves
/// several (4x faster, but a grain's normals moved by 2.4 degrees on average, 11 at worst:
/// its bumps turn the normals within a cluster), and a branch-free polynomial for every
/// candidate (not vectorised by the compiler, 1.1 s).
class BallGaussian {
 public:
  BallGaussian() {
    for (int i = 0; i <= kIntervals; ++i) node_[i] = std::exp(-2.0 * i / kIntervals);
  }
  double operator()(double t) const {
    const double u = t * kIntervals;
    const int i = std::min(static_cast<int>(u), kIntervals - 1);
    return node_[i] + (u - i) * (node_[i + 1] - node_[i]);
  }

 private:
  static constexpr int kIntervals = 4096;
  std::array<double, kIntervals + 1> node_;
};

/// For each vertex v, visit(v, u, w) for every vertex u within `radius` of it that faces its
/// way (n_u · n_v > 0), w the Gaussian of standard deviation radius/2 in their distance, the
/// u in the order of the 27 cells around v's (x, then y, then z offsets) and by index within a
/// cell. The cells in parallel, so `visit` may write v's entries only. At the renderer's 1.2 mm
/// the ball holds a third of a grain's vertices and the 27 cells 71% (103 and 224 million pairs
/// of 17,800 vertices): the pairs in the ball are the cost, so finer cells that skip those out
/// of reach saved only 12%.
template <class Visit>
void for_each_ball_neighbour(const MeshVertices& V, const MeshVertices& unit, double radius, Visit visit) {
  const CellBuckets b = bucket_vertices(V, unit, radius);
  static const BallGaussian gaussian;
  const double r2 = radius * radius;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, b.keys.size(), 1), [&](const auto& range) {  // ~40 cells a grain
    std::vector<std::pair<int, int>> around;  // the slots [begin, end) of the cells around c
    for (size_t c = range.begin(); c < range.end(); ++c) {
      around.clear();
      const CellKey k = b.keys[c];
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = -1; dz <= 1; ++dz)
            if (const auto it = b.cell.find({k.x + dx, k.y + dy, k.z + dz}); it != b.cell.end())
              around.emplace_back(b.begin[it->second], b.begin[it->second + 1]);
      for (int s = b.begin[c]; s < b.begin[c + 1]; ++s)
        for (const auto& [first, last] : around)
          for (int t = first; t < last; ++t) {
            const double d2 = (b.position[t] - b.position[s]).squaredNorm();
            if (d2 > r2 || b.normal[t].dot(b.normal[s]) <= 0.0) continue;
            visit(b.order[s], b.order[t], gaussian(d2 / r2));
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
