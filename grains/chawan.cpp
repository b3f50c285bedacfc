// Surface of revolution of the chawan's profile; see chawan.hpp.
#include "grains/chawan.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "grains/surface_measures.hpp"

namespace rice::grains {
namespace {

/// The profile (r, z) from the bottom of the foot on the axis, out along the foot, up the
/// outer wall, over the rim and down the inner wall to the inside bottom on the axis.
std::vector<Eigen::Vector2d> profile(const ChawanShape& s) {
  const double outer_b = s.height - s.foot_height;  // outer wall: ellipse about (0, height)
  const double inner_a = s.rim_radius - s.wall_thickness, inner_b = s.inner_depth;
  const auto outer_z = [&](double r) { return s.height - outer_b * std::sqrt(1.0 - (r / s.rim_radius) * (r / s.rim_radius)); };
  std::vector<Eigen::Vector2d> p = {{0.0, 0.0}, {s.foot_radius, 0.0}};
  const double first = std::asin(s.foot_radius / s.rim_radius);
  for (int k = 0; k <= s.wall_points; ++k) {
    const double theta = first + (M_PI / 2 - first) * k / s.wall_points;
    const double r = s.rim_radius * std::sin(theta);
    p.emplace_back(r, k == 0 ? outer_z(r) : s.height - outer_b * std::cos(theta));
  }
  for (int k = s.wall_points; k >= 0; --k) {
    const double theta = M_PI / 2 * k / s.wall_points;
    p.emplace_back(inner_a * std::sin(theta), s.height - inner_b * std::cos(theta));
  }
  return p;  // ends at (0, height − inner_depth)
}

}  // namespace

void validate(const ChawanShape& s) {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("chawan: " + what);
  };
  for (const double v : {s.rim_radius, s.height, s.inner_depth, s.wall_thickness, s.foot_radius, s.foot_height})
    require(std::isfinite(v) && v > 0.0, "every size must be positive and finite");
  require(s.wall_thickness < 0.5 * s.rim_radius, "wall thickness must be under half the rim radius");
  require(s.foot_radius < s.rim_radius - s.wall_thickness, "foot radius must lie inside the inner rim");
  require(s.foot_height < s.height - s.inner_depth, "the foot must end below the inside bottom (foot height < height − inner depth)");
  require(s.wall_points >= 2 && s.segments >= 8, "needs wall_points >= 2 and segments >= 8");
  // The inner wall must stay above the outer one at every radius inside it.
  const double outer_b = s.height - s.foot_height, inner_a = s.rim_radius - s.wall_thickness;
  for (int k = 0; k < 100; ++k) {
    const double r = inner_a * k / 100.0;
    const double outer = r < s.foot_radius ? 0.0 : s.height - outer_b * std::sqrt(1.0 - std::pow(r / s.rim_radius, 2));
    const double inner = s.height - s.inner_depth * std::sqrt(1.0 - std::pow(r / inner_a, 2));
    require(inner > outer, "the inner wall meets the outer wall at radius " + std::to_string(r) + " m");
  }
}

ChawanShape scaled(const ChawanShape& shape, double factor) {
  ChawanShape s = shape;
  for (double* size : {&s.rim_radius, &s.height, &s.inner_depth, &s.wall_thickness, &s.foot_radius, &s.foot_height})
    *size *= factor;
  return s;
}

SurfaceMesh make_chawan(const ChawanShape& shape) {
  validate(shape);
  const std::vector<Eigen::Vector2d> p = profile(shape);
  const int rings = static_cast<int>(p.size()) - 2;  // profile points off the axis
  const int n = shape.segments;
  SurfaceMesh mesh{Vertices(2 + rings * n, 3), Triangles(2 * n * rings, 3)};
  mesh.V.row(0) << 0.0, 0.0, p.front().y();
  for (int ring = 0; ring < rings; ++ring)
    for (int k = 0; k < n; ++k) {
      const double phi = 2.0 * M_PI * k / n;
      mesh.V.row(1 + ring * n + k) << p[ring + 1].x() * std::cos(phi), p[ring + 1].x() * std::sin(phi), p[ring + 1].y();
    }
  const int top = 1 + rings * n;
  mesh.V.row(top) << 0.0, 0.0, p.back().y();
  const auto at = [&](int ring, int k) { return 1 + ring * n + (k % n); };
  int f = 0;
  for (int k = 0; k < n; ++k) mesh.F.row(f++) << 0, at(0, k + 1), at(0, k);
  for (int ring = 0; ring + 1 < rings; ++ring)
    for (int k = 0; k < n; ++k) {
      mesh.F.row(f++) << at(ring, k), at(ring, k + 1), at(ring + 1, k + 1);
      mesh.F.row(f++) << at(ring, k), at(ring + 1, k + 1), at(ring + 1, k);
    }
  for (int k = 0; k < n; ++k) mesh.F.row(f++) << top, at(rings - 1, k), at(rings - 1, k + 1);
  mesh.F.conservativeResize(f, 3);
  if (enclosed_volume(mesh) < 0.0) flip_orientation(mesh);
  return mesh;
}

}  // namespace rice::grains
