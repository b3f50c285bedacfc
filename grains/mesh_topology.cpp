// Closed/manifold checks by directed-edge counting and vertex-link walks.
#include "grains/mesh_topology.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace rice::grains {
namespace {

std::string edge_name(int a, int b) {
  return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

std::optional<std::string> face_index_defect(const SurfaceMesh& mesh) {
  const Eigen::Index n = mesh.V.rows();
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (mesh.F(f, k) < 0 || mesh.F(f, k) >= n)
        return "face " + std::to_string(f) + " refers to vertex " + std::to_string(mesh.F(f, k)) +
               ", but the mesh has " + std::to_string(n) + " vertices";
    if (mesh.F(f, 0) == mesh.F(f, 1) || mesh.F(f, 1) == mesh.F(f, 2) || mesh.F(f, 2) == mesh.F(f, 0))
      return "face " + std::to_string(f) + " repeats a vertex (degenerate triangle)";
  }
  return std::nullopt;
}

// Every undirected edge must be used exactly once in each direction.
std::optional<std::string> edge_defect(const SurfaceMesh& mesh) {
  std::map<std::pair<int, int>, std::vector<int>> faces_of_directed_edge;
  for (int f = 0; f < static_cast<int>(mesh.F.rows()); ++f)
    for (int k = 0; k < 3; ++k)
      faces_of_directed_edge[{mesh.F(f, k), mesh.F(f, (k + 1) % 3)}].push_back(f);
  for (const auto& [edge, faces] : faces_of_directed_edge) {
    const auto [a, b] = edge;
    const auto reverse = faces_of_directed_edge.find({b, a});
    const size_t reverse_count = reverse == faces_of_directed_edge.end() ? 0 : reverse->second.size();
    const size_t total = faces.size() + reverse_count;
    if (total == 1)
      return edge_name(a, b) + " belongs to face " + std::to_string(faces[0]) +
             " only: the mesh is not closed (a hole's boundary)";
    if (total > 2)
      return edge_name(a, b) + " is shared by " + std::to_string(total) +
             " faces: the mesh is not manifold";
    if (faces.size() == 2)
      return edge_name(a, b) + " is used in the same direction by faces " + std::to_string(faces[0]) +
             " and " + std::to_string(faces[1]) + ": the faces are not consistently oriented";
  }
  return std::nullopt;
}

// With manifold edges, the link of each vertex is a union of cycles; more than one cycle
// means several fans meet at the vertex (a pinch point).
std::optional<std::string> vertex_defect(const SurfaceMesh& mesh) {
  std::vector<std::unordered_map<int, int>> link(mesh.V.rows());
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      link[mesh.F(f, k)][mesh.F(f, (k + 1) % 3)] = mesh.F(f, (k + 2) % 3);
  for (size_t v = 0; v < link.size(); ++v) {
    if (link[v].empty()) continue;
    const int start = link[v].begin()->first;
    size_t walked = 0;
    int current = start;
    do {
      current = link[v].at(current);
      ++walked;
    } while (current != start && walked <= link[v].size());
    if (walked != link[v].size())
      return "vertex " + std::to_string(v) + " joins " + std::to_string(link[v].size()) +
             " faces that do not form one fan: the mesh is not manifold there";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> closed_manifold_defect(const SurfaceMesh& mesh) {
  if (mesh.F.rows() == 0) return std::string("the mesh has no faces");
  if (auto defect = face_index_defect(mesh)) return defect;
  if (auto defect = edge_defect(mesh)) return defect;
  return vertex_defect(mesh);
}

void require_closed_manifold(const SurfaceMesh& mesh, const std::string& source) {
  if (const auto defect = closed_manifold_defect(mesh)) throw std::invalid_argument(source + ": " + *defect);
}

int connected_component_count(const SurfaceMesh& mesh) {
  std::vector<int> parent(mesh.V.rows());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 1; k < 3; ++k) parent[find(mesh.F(f, k))] = find(mesh.F(f, 0));
  std::vector<bool> is_root(mesh.V.rows(), false);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) is_root[find(mesh.F(f, 0))] = true;
  return static_cast<int>(std::count(is_root.begin(), is_root.end(), true));
}

std::vector<BoundaryFace> boundary_faces(const Tets& T) {
  constexpr int faces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  struct Use {
    int count = 0;
    BoundaryFace face;
  };
  std::map<std::array<int, 3>, Use> uses;  // keyed by the sorted corners
  for (int t = 0; t < static_cast<int>(T.rows()); ++t)
    for (const auto& f : faces) {
      const Eigen::Vector3i corners(T(t, f[0]), T(t, f[1]), T(t, f[2]));
      std::array<int, 3> key = {corners[0], corners[1], corners[2]};
      std::sort(key.begin(), key.end());
      Use& use = uses[key];
      ++use.count;
      use.face = {corners, t};
    }
  std::vector<BoundaryFace> boundary;
  for (const auto& [key, use] : uses)
    if (use.count == 1) boundary.push_back(use.face);
  return boundary;
}

SurfaceMesh boundary_surface(const VolumeMesh& mesh) {
  const std::vector<BoundaryFace> faces = boundary_faces(mesh.T);
  SurfaceMesh surface{mesh.V, Triangles(faces.size(), 3)};
  for (size_t f = 0; f < faces.size(); ++f) surface.F.row(f) = faces[f].corners.transpose();
  return surface;
}

}  // namespace rice::grains
