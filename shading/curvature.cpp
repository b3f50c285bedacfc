// Jet-fitted vertex mean curvature (curvature.hpp).
#include "shading/curvature.hpp"

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace rice::shading {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using JetFitting = CGAL::Monge_via_jet_fitting<Kernel>;

void check_mesh(const MeshVertices& V, const MeshTriangles& F) {
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= V.rows())) {
    throw std::invalid_argument("vertex_mean_curvature: a triangle names a vertex outside 0.." +
                                std::to_string(V.rows() - 1));
  }
}

// Vertex neighbours from the triangles, compressed rows: neighbours of v are
// adjacency[offsets[v] .. offsets[v+1]).
struct Adjacency {
  std::vector<int> offsets, neighbours;
};

Adjacency vertex_adjacency(Eigen::Index vertex_count, const MeshTriangles& F) {
  std::vector<std::vector<int>> lists(static_cast<std::size_t>(vertex_count));
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      lists[F(f, c)].push_back(F(f, (c + 1) % 3));
      lists[F(f, c)].push_back(F(f, (c + 2) % 3));
    }
  }
  Adjacency adjacency;
  adjacency.offsets.push_back(0);
  for (auto& list : lists) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    adjacency.neighbours.insert(adjacency.neighbours.end(), list.begin(), list.end());
    adjacency.offsets.push_back(static_cast<int>(adjacency.neighbours.size()));
  }
  return adjacency;
}

// The vertex first (the point the Monge form is taken at), then its rings in breadth-first
// order. `mark` holds, per vertex, the stamp of the last gathering that took it; each call
// takes a new stamp.
void gather_rings(const Adjacency& adjacency, int seed, int rings, std::vector<int>& mark, int& stamp,
                  std::vector<int>& out) {
  ++stamp;
  out.assign(1, seed);
  mark[seed] = stamp;
  std::size_t ring_begin = 0;
  for (int r = 0; r < rings; ++r) {
    const std::size_t ring_end = out.size();
    for (std::size_t k = ring_begin; k < ring_end; ++k) {
      const int v = out[k];
      for (int n = adjacency.offsets[v]; n < adjacency.offsets[v + 1]; ++n) {
        const int w = adjacency.neighbours[n];
        if (mark[w] != stamp) {
          mark[w] = stamp;
          out.push_back(w);
        }
      }
    }
    ring_begin = ring_end;
  }
}

}  // namespace

MeshVertices vertex_normals(const MeshVertices& V, const MeshTriangles& F) {
  check_mesh(V, F);
  MeshVertices N = MeshVertices::Zero(V.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::RowVector3d area_normal = (b - a).cross(c - a).transpose();
    for (int k = 0; k < 3; ++k) N.row(F(f, k)) += area_normal;
  }
  for (Eigen::Index v = 0; v < N.rows(); ++v) {
    const double length = N.row(v).norm();
    if (length > 0.0) N.row(v) /= length;
  }
  return N;
}

Eigen::VectorXd vertex_mean_curvature(const MeshVertices& V, const MeshTriangles& F,
                                      const CurvatureOptions& options) {
  check_mesh(V, F);
  const int degree = options.jet_degree;
  if (degree < 2 || degree > 4 || options.rings < 1) {
    throw std::invalid_argument("vertex_mean_curvature: jet_degree must be 2-4 and rings >= 1, got " +
                                std::to_string(degree) + " and " + std::to_string(options.rings));
  }
  // A degree-d jet has (d+1)(d+2)/2 coefficients; rings are widened until the fit is
  // overdetermined by half as many points again, or until the vertex's piece of surface has
  // no more vertices to give.
  const std::size_t coefficients = static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);
  const std::size_t wanted = coefficients * 3 / 2;
  constexpr int kMaxRings = 8;
  const Adjacency adjacency = vertex_adjacency(V.rows(), F);
  const MeshVertices normals = vertex_normals(V, F);

  Eigen::VectorXd H(V.rows());
  std::vector<int> mark(static_cast<std::size_t>(V.rows()), 0), neighbourhood;
  int stamp = 0;
  std::vector<Kernel::Point_3> points;
  JetFitting fitting;
  for (int v = 0; v < static_cast<int>(V.rows()); ++v) {
    int rings = options.rings;
    gather_rings(adjacency, v, rings, mark, stamp, neighbourhood);
    for (std::size_t before = 0; neighbourhood.size() < wanted && neighbourhood.size() > before && rings < kMaxRings;) {
      before = neighbourhood.size();
      gather_rings(adjacency, v, ++rings, mark, stamp, neighbourhood);
    }
    if (neighbourhood.size() < 3) {
      throw std::runtime_error("vertex_mean_curvature: vertex " + std::to_string(v) + " belongs to no triangle");
    }
    if (neighbourhood.size() < coefficients) {
      // A fragment too small for a jet (a few vertices split off a porous surface): the
      // curvature of a sphere of its mean radius about its centroid.
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (const int w : neighbourhood) centroid += V.row(w).transpose();
      centroid /= static_cast<double>(neighbourhood.size());
      double radius = 0.0;
      for (const int w : neighbourhood) radius += (V.row(w).transpose() - centroid).norm();
      radius /= static_cast<double>(neighbourhood.size());
      H(v) = radius > 0.0 ? 1.0 / radius : 0.0;
      continue;
    }
    points.clear();
    for (const int w : neighbourhood) points.emplace_back(V(w, 0), V(w, 1), V(w, 2));
    JetFitting::Monge_form monge = fitting(points.begin(), points.end(), degree, 2);
    monge.comply_wrt_given_normal(Kernel::Vector_3(normals(v, 0), normals(v, 1), normals(v, 2)));
    // Monge form z = ½(k1 x² + k2 y²) + … with z along the outward normal: a convex surface
    // bends away from it, so its k are negative; H is positive there.
    H(v) = -0.5 * (monge.principal_curvatures(0) + monge.principal_curvatures(1));
  }
  return H;
}

}  // namespace rice::shading
