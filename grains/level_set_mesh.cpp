// volumeToMesh wrapper (see level_set_mesh.hpp).
#include "grains/level_set_mesh.hpp"

#include <openvdb/tools/VolumeToMesh.h>

#include <stdexcept>
#include <vector>

#include "grains/surface_measures.hpp"

namespace rice::grains {

SurfaceMesh level_set_to_mesh(const openvdb::FloatGrid& grid, double adaptivity) {
  if (!(adaptivity >= 0.0 && adaptivity <= 1.0))
    throw std::invalid_argument("mesh adaptivity must be in [0, 1], got " + std::to_string(adaptivity));
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, 0.0, adaptivity);

  SurfaceMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v)
    mesh.V.row(static_cast<Eigen::Index>(v)) << points[v].x(), points[v].y(), points[v].z();
  mesh.F.resize(static_cast<Eigen::Index>(triangles.size() + 2 * quads.size()), 3);
  Eigen::Index f = 0;
  for (const openvdb::Vec3I& t : triangles) mesh.F.row(f++) << int(t[0]), int(t[1]), int(t[2]);
  for (const openvdb::Vec4I& q : quads) {
    mesh.F.row(f++) << int(q[0]), int(q[1]), int(q[2]);
    mesh.F.row(f++) << int(q[0]), int(q[2]), int(q[3]);
  }
  // volumeToMesh's winding follows the grid's sign convention; make it outward.
  if (enclosed_volume(mesh) < 0.0) flip_orientation(mesh);
  return mesh;
}

}  // namespace rice::grains
