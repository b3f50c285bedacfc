// Edge-collapse simplification; see mesh_simplification.hpp.
#include "grains/mesh_simplification.hpp"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

namespace rice::grains {
namespace {

using SimplificationKernel = CGAL::Simple_cartesian<double>;
using CollapsibleMesh = CGAL::Surface_mesh<SimplificationKernel::Point_3>;

CollapsibleMesh to_collapsible(const SurfaceMesh& mesh) {
  std::vector<SimplificationKernel::Point_3> points;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) points.emplace_back(mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2));
  std::vector<std::array<std::size_t, 3>> faces;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    faces.push_back({static_cast<std::size_t>(mesh.F(f, 0)), static_cast<std::size_t>(mesh.F(f, 1)),
                     static_cast<std::size_t>(mesh.F(f, 2))});
  CollapsibleMesh out;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, out);
  return out;
}

SurfaceMesh from_collapsible(const CollapsibleMesh& mesh) {
  SurfaceMesh out;
  out.V.resize(mesh.number_of_vertices(), 3);
  out.F.resize(mesh.number_of_faces(), 3);
  Eigen::Index row = 0;
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    out.V.row(row++) << p.x(), p.y(), p.z();
  }
  row = 0;
  for (const auto f : mesh.faces()) {
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) out.F(row, k++) = static_cast<int>(v);
    ++row;
  }
  return out;
}

}  // namespace

SurfaceMesh simplified(const SurfaceMesh& mesh, int max_vertices) {
  if (max_vertices < 4) throw std::invalid_argument("simplified: need at least 4 vertices");
  if (mesh.V.rows() <= max_vertices) return mesh;
  CollapsibleMesh cgal = to_collapsible(mesh);
  if (cgal.number_of_vertices() != static_cast<CollapsibleMesh::size_type>(mesh.V.rows()) || !CGAL::is_closed(cgal))
    throw std::invalid_argument("simplified: the mesh is not a closed manifold");
  // A closed triangle mesh has E = 3 (V − χ) edges, χ = V − F/2 its Euler characteristic
  // (2 per sphere-like part: a porous grain's pores are parts of their own); edge collapses
  // keep χ, so V = max_vertices at E = 3 (max_vertices − χ).
  const long chi = static_cast<long>(mesh.V.rows()) - static_cast<long>(mesh.F.rows()) / 2;
  const std::size_t edges = static_cast<std::size_t>(std::max(0L, 3 * (max_vertices - chi)));
  CGAL::Surface_mesh_simplification::Count_stop_predicate<CollapsibleMesh> stop(edges);  // stops below `edges` edges
  CGAL::Surface_mesh_simplification::edge_collapse(cgal, stop);
  cgal.collect_garbage();
  return from_collapsible(cgal);
}

}  // namespace rice::grains
