// Tet quality measures (see tet_quality.hpp).
#include "grains/tet_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rice::grains {
namespace {

// Circumradius of a tet: |a|²(b×c) + |b|²(c×a) + |c|²(a×b) over 2 a·(b×c), edges from one vertex.
double circumradius(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const Vec3 a = p1 - p0, b = p2 - p0, c = p3 - p0;
  const Vec3 numerator = a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b);
  return numerator.norm() / std::abs(2.0 * a.dot(b.cross(c)));
}

// Interior dihedral angle at edge (i, j): the angle between the parts of p_k − p_i and
// p_l − p_i perpendicular to the edge (k, l the other two vertices).
double dihedral_angle(const std::array<Vec3, 4>& p, int i, int j, int k, int l) {
  const Vec3 edge = p[j] - p[i];
  const Vec3 to_k = p[k] - p[i], to_l = p[l] - p[i];
  const Vec3 u = (to_k - to_k.dot(edge) / edge.squaredNorm() * edge).normalized();
  const Vec3 v = (to_l - to_l.dot(edge) / edge.squaredNorm() * edge).normalized();
  return std::acos(std::clamp(u.dot(v), -1.0, 1.0));
}

}  // namespace

double tet_signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

double total_volume(const VolumeMesh& mesh) {
  double volume = 0.0;
  for (Eigen::Index t = 0; t < mesh.T.rows(); ++t) {
    const auto [a, b, c, d] = tet_corners(mesh, t);
    volume += tet_signed_volume(a, b, c, d);
  }
  return volume;
}

TetQuality measure_tet_quality(const VolumeMesh& mesh) {
  TetQuality q;
  if (mesh.T.rows() == 0) return q;
  q.min_volume = std::numeric_limits<double>::infinity();
  q.min_dihedral_degrees = 180.0;
  constexpr int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for (Eigen::Index t = 0; t < mesh.T.rows(); ++t) {
    const std::array<Vec3, 4> p = tet_corners(mesh, t);
    q.min_volume = std::min(q.min_volume, tet_signed_volume(p[0], p[1], p[2], p[3]));
    double shortest = std::numeric_limits<double>::infinity();
    for (const auto& e : edges) {
      const double angle = dihedral_angle(p, e[0], e[1], e[2], e[3]) * 180.0 / std::numbers::pi;
      q.min_dihedral_degrees = std::min(q.min_dihedral_degrees, angle);
      q.max_dihedral_degrees = std::max(q.max_dihedral_degrees, angle);
      shortest = std::min(shortest, (p[e[1]] - p[e[0]]).norm());
    }
    const double ratio = circumradius(p[0], p[1], p[2], p[3]) / shortest;
    q.max_radius_edge_ratio = std::max(q.max_radius_edge_ratio, ratio);
    q.mean_radius_edge_ratio += ratio / double(mesh.T.rows());
  }
  return q;
}

}  // namespace rice::grains
