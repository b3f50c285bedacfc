// Barycentric embedding (see embedding.hpp). Brute force over tets: simulation meshes have
// tens of tets, so a spatial index would cost more than it saves.
#include "grains/embedding.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "grains/mesh_topology.hpp"

namespace rice::grains {


Eigen::Vector4d barycentric_coordinates(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  Eigen::Matrix3d edges;
  edges << b - a, c - a, d - a;
  const Vec3 w = edges.partialPivLu().solve(p - a);
  return {1.0 - w.sum(), w.x(), w.y(), w.z()};
}

double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 normal = (b - a).cross(c - a);
  const double area2 = normal.squaredNorm();
  if (area2 > 0.0) {
    // Inside the prism over the triangle: the distance to its plane.
    const Vec3 q = p - normal * (p - a).dot(normal) / area2;
    const double u = (c - b).cross(q - b).dot(normal), v = (a - c).cross(q - c).dot(normal),
                 w = (b - a).cross(q - a).dot(normal);
    if (u >= 0.0 && v >= 0.0 && w >= 0.0) return (p - q).norm();
  }
  const auto segment = [&](const Vec3& s, const Vec3& e) {
    const Vec3 d = e - s;
    const double t = d.squaredNorm() > 0.0 ? std::clamp((p - s).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return (p - (s + t * d)).norm();
  };
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

Embedding embed_points(const Vertices& points, const VolumeMesh& mesh) {
  if (mesh.T.rows() == 0) throw std::invalid_argument("embedding: the simulation mesh has no tets");
  const std::vector<BoundaryFace> boundary = boundary_faces(mesh.T);
  const auto coordinates = [&](const Vec3& p, int t) {
    const auto [a, b, c, d] = tet_corners(mesh, t);
    return barycentric_coordinates(p, a, b, c, d);
  };
  Embedding embedding;
  embedding.tet.resize(points.rows());
  embedding.weights.resize(points.rows(), 4);
  tbb::parallel_for(Eigen::Index(0), points.rows(), [&](Eigen::Index i) {
    const Vec3 p = points.row(i);
    int best = -1;
    double best_min_weight = -std::numeric_limits<double>::infinity();
    Eigen::Vector4d best_weights = Eigen::Vector4d::Zero();
    for (int t = 0; t < static_cast<int>(mesh.T.rows()); ++t) {
      const Eigen::Vector4d w = coordinates(p, t);
      if (w.minCoeff() > best_min_weight) {
        best_min_weight = w.minCoeff();
        best = t;
        best_weights = w;
      }
    }
    constexpr double kInsideTolerance = -1e-12;
    if (best_min_weight < kInsideTolerance) {  // outside: the tet of the nearest boundary face
      double nearest = std::numeric_limits<double>::infinity();
      for (const BoundaryFace& face : boundary) {
        const double distance = point_triangle_distance(p, mesh.V.row(face.corners[0]), mesh.V.row(face.corners[1]),
                                                        mesh.V.row(face.corners[2]));
        if (distance < nearest) {
          nearest = distance;
          best = face.tet;
        }
      }
      best_weights = coordinates(p, best);
    }
    embedding.tet[i] = best;
    embedding.weights.row(i) = best_weights.transpose();
  });
  return embedding;
}

Vertices apply_embedding(const Embedding& embedding, const Vertices& x, const Tets& T) {
  Vertices result(embedding.tet.size(), 3);
  for (Eigen::Index i = 0; i < embedding.tet.size(); ++i) result.row(i) = embedded_point(embedding, i, x, T).transpose();
  return result;
}

Vertices carry_normals(const Embedding& embedding, const Vertices& N, const Vertices& X, const Vertices& x,
                       const Tets& T) {
  const auto edges = [&](const Vertices& P, int t) {
    Eigen::Matrix3d D;
    for (int k = 0; k < 3; ++k) D.col(k) = (P.row(T(t, k + 1)) - P.row(T(t, 0))).transpose();
    return D;
  };
  std::vector<Eigen::Matrix3d> inverse_transpose(T.rows());  // F⁻ᵀ per tet, made when first needed
  std::vector<char> made(T.rows(), 0);
  Vertices result(N.rows(), 3);
  for (Eigen::Index i = 0; i < N.rows(); ++i) {
    const int t = embedding.tet[i];
    if (!made[t]) {
      inverse_transpose[t] = (edges(x, t) * edges(X, t).inverse()).inverse().transpose();
      made[t] = 1;
    }
    result.row(i) = (inverse_transpose[t] * N.row(i).transpose()).normalized().transpose();
  }
  return result;
}

}  // namespace rice::grains
