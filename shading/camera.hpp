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

  /// The camera's frame for images of width/height `aspect`, computed once per image.
  struct Frame {
    Eigen::Vector3d position, forward, right, up;  ///< right and up scaled to the film's half sizes
    double aperture = 0.0, focus = 1.0;

    /// The ray through film point (u, v) ∈ [0, 1]² (u right, v down, like image rows), with
    /// lens sample (a, b) ∈ [0, 1]² (unused for a pinhole).
    CameraRay ray(double u, double v, double a, double b) const {
      const Eigen::Vector3d d = forward + (2 * u - 1) * right + (1 - 2 * v) * up;
      if (aperture <= 0.0) return {position.cast<float>(), d.normalized().cast<float>()};
      // Thin lens: the point at focus distance along the pinhole ray stays sharp; the origin
      // moves over a disc of the aperture's radius.
      const Eigen::Vector3d focal_point = position + d * focus;  // d·forward = 1
      const double r = aperture * std::sqrt(a), phi = 2 * std::numbers::pi * b;
      const Eigen::Vector3d origin =
          position + r * (std::cos(phi) * right.normalized() + std::sin(phi) * up.normalized());
      return {origin.cast<float>(), (focal_point - origin).normalized().cast<float>()};
    }
  };

  Frame frame(double aspect) const {
    Frame f;
    f.position = position;
    f.forward = (target - position).normalized();
    const Eigen::Vector3d right = f.forward.cross(up).normalized();
    const double half_height = std::tan(0.5 * vertical_fov_degrees * std::numbers::pi / 180.0);
    f.right = aspect * half_height * right;
    f.up = half_height * right.cross(f.forward);
    f.aperture = aperture_radius;
    f.focus = focus_distance > 0.0 ? focus_distance : (target - position).norm();
    return f;
  }

  /// One ray, for a single query (a renderer takes frame() once and asks it).
  CameraRay ray(double u, double v, double a, double b, double aspect) const { return frame(aspect).ray(u, v, a, b); }
};

}  // namespace rice::shading
