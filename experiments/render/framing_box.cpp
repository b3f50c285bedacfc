// The box a render's default camera frames; see framing_box.hpp.
#include "experiments/render/framing_box.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rice::experiments {
namespace {

/// The k-th smallest of `values`, which it reorders.
double ranked(std::vector<double>& values, size_t k) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

/// The distance from `target` along `d` (unit, towards the camera) at which every corner q of
/// the box lies within the image: |q·r| ≤ t_x (D − q·d) and |q·u| ≤ t_y (D − q·d).
double fitting_distance(const std::array<Eigen::Vector3d, 8>& corners, const Eigen::Vector3d& target,
                        const Eigen::Vector3d& d, const Eigen::Vector3d& r, const Eigen::Vector3d& u, double tx,
                        double ty) {
  double distance = 0.0;
  for (const Eigen::Vector3d& p : corners) {
    const Eigen::Vector3d q = p - target;
    distance = std::max({distance, q.dot(d) + std::abs(q.dot(r)) / tx, q.dot(d) + std::abs(q.dot(u)) / ty});
  }
  return distance;
}

}  // namespace

shading::Camera framing_camera(const Eigen::AlignedBox3d& bounds, double elevation_degrees, double azimuth_degrees,
                               double vertical_fov_degrees, double aspect) {
  constexpr double kDegree = std::numbers::pi / 180.0, kMargin = 1.05;
  const double e = elevation_degrees * kDegree, a = azimuth_degrees * kDegree;
  const Eigen::Vector3d d(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
  shading::Camera camera;
  camera.vertical_fov_degrees = vertical_fov_degrees;
  const Eigen::Vector3d r = (-d).cross(camera.up).normalized(), u = r.cross(-d);
  const double ty = std::tan(0.5 * vertical_fov_degrees * kDegree) / kMargin, tx = ty * aspect;
  std::array<Eigen::Vector3d, 8> corners;
  for (int k = 0; k < 8; ++k) corners[k] = bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k));
  Eigen::Vector3d target = bounds.center();
  double distance;
  for (int pass = 0; pass < 4; ++pass) {  // centre the projections: each pass halves the offset or better
    distance = fitting_distance(corners, target, d, r, u, tx, ty);
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
    for (const Eigen::Vector3d& p : corners) {
      const Eigen::Vector3d q = p - target;
      const Eigen::Vector2d film = Eigen::Vector2d(q.dot(r), q.dot(u)) / (distance - q.dot(d));
      lo = lo.cwiseMin(film);
      hi = hi.cwiseMax(film);
    }
    const Eigen::Vector2d mid = 0.5 * (lo + hi) * distance;
    target += mid.x() * r + mid.y() * u;
  }
  distance = fitting_distance(corners, target, d, r, u, tx, ty);
  camera.target = target;
  camera.position = target + distance * d;
  return camera;
}

Eigen::AlignedBox3d framing_box(const std::vector<Eigen::AlignedBox3d>& grains) {
  Eigen::AlignedBox3d kept;
  if (grains.empty()) return kept;
  double diagonal = 0.0;
  for (const auto& box : grains) diagonal = std::max(diagonal, box.diagonal().norm());
  Eigen::AlignedBox3d bulk;
  const size_t n = grains.size(), tail = (n - 1) / 100;  // the 1st and 99th percentiles' ranks
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> centres;
    for (const auto& box : grains) centres.push_back(box.center()[axis]);
    const double lo = ranked(centres, tail), hi = ranked(centres, n - 1 - tail);
    const double margin = 0.1 * (hi - lo) + diagonal;
    bulk.min()[axis] = lo - margin;
    bulk.max()[axis] = hi + margin;
  }
  for (const auto& box : grains)
    if (bulk.contains(box.center())) kept.extend(box);
  return kept;
}

}  // namespace rice::experiments
