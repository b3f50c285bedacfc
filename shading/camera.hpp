// Pinhole and thin-lens camera: film coordinates and a lens sample to a world-space ray.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <numbers>

namespace rice::shading {

struct CameraRay {
  Eigen::Vector3f origin, direction;  ///< direction unit length
};

/// Looks from `position` at `target`; `up` need not be orthogonal to the view direction.
/// aperture_radius = 0 is a pinhole; otherwise the thin lens focuses at focus_distance
/// (0: the distance to the target).
struct Camera {
  Eigen::Vector3d position{0, -0.2, 0.1};
  Eigen::Vector3d target{0, 0, 0};
  Eigen::Vector3d up{0, 0, 1};
  double vertical_fov_degrees = 30.0;
  double aperture_radius = 0.0;  ///< [m]
  double focus_distance = 0.0;   ///< [m]

  /// The ray through film point (u, v) ∈ [0, 1]² (u right, v down, like image rows), with lens
  /// sample (a, b) ∈ [0, 1]² (unused for a pinhole), for an image width/height of `aspect`.
  CameraRay ray(double u, double v, double a, double b, double aspect) const {
    const Eigen::Vector3d forward = (target - position).normalized();
    const Eigen::Vector3d right = forward.cross(up).normalized();
    const Eigen::Vector3d true_up = right.cross(forward);
    const double half_height = std::tan(0.5 * vertical_fov_degrees * std::numbers::pi / 180.0);
    const Eigen::Vector3d d = (forward + (2 * u - 1) * aspect * half_height * right + (1 - 2 * v) * half_height * true_up);
    if (aperture_radius <= 0.0) return {position.cast<float>(), d.normalized().cast<float>()};
    // Thin lens: the point at focus distance along the pinhole ray stays sharp; the origin
    // moves over a disc of the aperture's radius (concentric mapping keeps strata compact).
    const double focus = focus_distance > 0.0 ? focus_distance : (target - position).norm();
    const Eigen::Vector3d focal_point = position + d * (focus / d.dot(forward));
    const double r = aperture_radius * std::sqrt(a), phi = 2 * std::numbers::pi * b;
    const Eigen::Vector3d origin = position + r * (std::cos(phi) * right + std::sin(phi) * true_up);
    return {origin.cast<float>(), (focal_point - origin).normalized().cast<float>()};
  }
};

}  // namespace rice::shading
