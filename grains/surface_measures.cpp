// Volume, area and extent of triangle surfaces.
#include "grains/surface_measures.hpp"

namespace rice::grains {

double enclosed_volume(const SurfaceMesh& mesh) {
  double six_volume = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const auto [a, b, c] = triangle_corners(mesh, f);
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

double surface_area(const SurfaceMesh& mesh) {
  double two_area = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const auto [a, b, c] = triangle_corners(mesh, f);
    two_area += (b - a).cross(c - a).norm();
  }
  return two_area / 2.0;
}

Vec3 bounding_box_extent(const Vertices& V) {
  if (V.rows() == 0) return Vec3::Zero();
  return (V.colwise().maxCoeff() - V.colwise().minCoeff()).transpose();
}

void flip_orientation(SurfaceMesh& mesh) { mesh.F.col(1).swap(mesh.F.col(2)); }

}  // namespace rice::grains
