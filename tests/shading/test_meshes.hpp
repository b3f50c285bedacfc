// Analytic test surfaces for the shading suite: an icosphere (a subdivided icosahedron
// projected onto the unit sphere), scaled into spheres and ellipsoids; and the camera the
// renderer tests look down with.
#pragma once

#include "shading/camera.hpp"
#include "shading/curvature.hpp"

#include <map>
#include <utility>

namespace rice::shading::test_support {

struct TestMesh {
  MeshVertices V;
  MeshTriangles F;
};

/// A camera at `height` on the z axis looking down at the origin, +y up in the image.
inline Camera looking_down(double height, double fov_degrees) {
  Camera c;
  c.position = {0, 0, height};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.vertical_fov_degrees = fov_degrees;
  return c;
}

/// Unit icosphere after `subdivisions` 1-to-4 splits: 10·4^s + 2 vertices.
inline TestMesh icosphere(int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& p : v) p.normalize();
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoints.try_emplace(key, static_cast<int>(v.size()));
      if (inserted) v.push_back((v[a] + v[b]).normalized());
      return it->second;
    };
    std::vector<Eigen::Vector3i> finer;
    for (const auto& tri : f) {
      const int ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]), ca = midpoint(tri[2], tri[0]);
      finer.insert(finer.end(), {{tri[0], ab, ca}, {tri[1], bc, ab}, {tri[2], ca, bc}, {ab, bc, ca}});
    }
    f = std::move(finer);
  }
  TestMesh mesh{MeshVertices(v.size(), 3), MeshTriangles(f.size(), 3)};
  for (std::size_t i = 0; i < v.size(); ++i) mesh.V.row(i) = v[i].transpose();
  for (std::size_t i = 0; i < f.size(); ++i) mesh.F.row(i) = f[i].transpose();
  return mesh;
}

/// The icosphere scaled by (a, b, c) along the axes: an ellipsoid.
inline TestMesh ellipsoid(int subdivisions, double a, double b, double c) {
  TestMesh mesh = icosphere(subdivisions);
  mesh.V = mesh.V * Eigen::Vector3d(a, b, c).asDiagonal();
  return mesh;
}

/// A sphere of radius `outer` with a closed spherical pore of radius `inner` at its centre:
/// the pore's triangles turned so that every normal points out of the material (into the
/// pore). Icospheres of `subdivisions`.
inline TestMesh hollow_sphere(int subdivisions, double outer, double inner) {
  const TestMesh shell = icosphere(subdivisions);
  TestMesh mesh{MeshVertices(2 * shell.V.rows(), 3), MeshTriangles(2 * shell.F.rows(), 3)};
  mesh.V << outer * shell.V, inner * shell.V;
  const MeshTriangles reversed = shell.F.rowwise().reverse();
  mesh.F << shell.F, reversed.array() + static_cast<int>(shell.V.rows());
  return mesh;
}

/// Mean curvature of the ellipsoid x²/a² + y²/b² + z²/c² = 1 at a point on it,
///   H = (a² + b² + c² − |p|²) / (2 a² b² c² (x²/a⁴ + y²/b⁴ + z²/c⁴)^{3/2}),
/// positive (the outward normal points away from the centre of curvature).
inline double ellipsoid_mean_curvature(const Eigen::Vector3d& p, double a, double b, double c) {
  const double a2 = a * a, b2 = b * b, c2 = c * c;
  const double q = p.x() * p.x() / (a2 * a2) + p.y() * p.y() / (b2 * b2) + p.z() * p.z() / (c2 * c2);
  return (a2 + b2 + c2 - p.squaredNorm()) / (2 * a2 * b2 * c2 * std::pow(q, 1.5));
}

}  // namespace rice::shading::test_support
