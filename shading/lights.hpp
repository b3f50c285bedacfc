// Lights of the renderer. Each is sampled by direction from a shading point: the sample
// carries radiance / pdf (solid angle), so a light's contribution is f · cos-like · sample.
//  - Sun: a distant disc of angular radius α giving irradiance E at normal incidence; sampled
//    uniformly over its cone (pdf 1 / 2π(1 − cos α)); L = E / (π sin²α).
//  - QuadLight: a one-sided parallelogram emitting radiance L on the side of edge_u × edge_v;
//    sampled uniformly over its area.
//  - Environment: radiance from every direction, constant or from a latitude–longitude image
//    (z up); sampled uniformly over the sphere, since the CDRF lets light in from behind the
//    terminator too.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <vector>

#include "shading/tangent_frame.hpp"

namespace rice::shading {

using Color = Eigen::Array3f;

struct LightSample {
  Eigen::Vector3f direction;  ///< unit, from the shading point towards the light
  float distance = 0.0f;      ///< to the light (infinity for sun and environment)
  Color weight = Color::Zero();  ///< radiance / pdf
};

struct Sun {
  Eigen::Vector3f direction{0.3f, -0.4f, 0.866f};  ///< towards the sun; normalised on use
  float angular_radius = 0.00465f;                 ///< [rad], the real sun's
  Color irradiance = Color::Constant(3.0f);        ///< E at normal incidence

  /// The sun's frame and weight, computed once per image.
  struct Sampler {
    Eigen::Vector3d w = Eigen::Vector3d::UnitZ(), t = Eigen::Vector3d::UnitX(), s = Eigen::Vector3d::UnitY();
    double one_minus_cos_max = 0.0;
    Color weight = Color::Zero();

    /// A direction uniform over the sun's cone, in double.
    Eigen::Vector3d direction(double a, double b) const {
      const double one_minus_cos = a * one_minus_cos_max;
      const double cos_t = 1.0 - one_minus_cos;
      const double sin_t = std::sqrt(std::max(0.0, one_minus_cos * (2.0 - one_minus_cos)));
      const double phi = 2.0 * std::numbers::pi * b;
      return (cos_t * w + sin_t * (std::cos(phi) * t + std::sin(phi) * s)).normalized();
    }

    LightSample sample(double a, double b) const {
      return {direction(a, b).cast<float>(), std::numeric_limits<float>::infinity(), weight};
    }
  };

  Sampler sampler() const {
    // In double with 1 − cos α = 2 sin²(α/2): in float, 1 − cos α of the real sun (1.1e-5)
    // keeps two digits and the irradiance came out 0.3% low.
    Sampler p;
    p.w = direction.cast<double>().normalized();
    std::tie(p.t, p.s) = tangent_frame(p.w);
    const double half = std::sin(0.5 * angular_radius);
    p.one_minus_cos_max = 2.0 * half * half;
    const double solid_angle = 2.0 * std::numbers::pi * p.one_minus_cos_max;
    const double sin_a = std::sin(angular_radius);
    p.weight = sin_a > 0.0 ? Color(irradiance * static_cast<float>(solid_angle / (std::numbers::pi * sin_a * sin_a)))
                           : irradiance;
    return p;
  }

  LightSample sample(double a, double b) const { return sampler().sample(a, b); }
};

struct QuadLight {
  Eigen::Vector3f corner{-0.1f, -0.1f, 0.4f};
  Eigen::Vector3f edge_u{0.2f, 0.0f, 0.0f}, edge_v{0.0f, 0.2f, 0.0f};
  Color radiance = Color::Constant(10.0f);  ///< emitted radiance

  /// Emits on the side edge_v × edge_u points to (downwards for the defaults).
  LightSample sample(const Eigen::Vector3f& from, double a, double b) const {
    const Eigen::Vector3f p = corner + static_cast<float>(a) * edge_u + static_cast<float>(b) * edge_v;
    const Eigen::Vector3f cross = edge_v.cross(edge_u);
    const float area = cross.norm();
    const Eigen::Vector3f n = cross / area;
    Eigen::Vector3f d = p - from;
    const float distance = d.norm();
    d /= distance;
    const float cos_light = -n.dot(d);
    if (cos_light <= 0.0f) return {d, distance, Color::Zero()};
    return {d, distance, radiance * (area * cos_light / (distance * distance))};
  }
};

struct Environment {
  Color constant = Color::Zero();
  /// Optional latitude–longitude radiance image, row 0 at the zenith (+z), u along φ from +x.
  int width = 0, height = 0;
  std::vector<Color> image;

  Color radiance(const Eigen::Vector3f& d) const {
    if (image.empty()) return constant;
    const float theta = std::acos(std::clamp(d.z(), -1.0f, 1.0f));
    float phi = std::atan2(d.y(), d.x());
    if (phi < 0) phi += 2.0f * std::numbers::pi_v<float>;
    const int x = std::min(width - 1, static_cast<int>(phi / (2.0f * std::numbers::pi_v<float>) * width));
    const int y = std::min(height - 1, static_cast<int>(theta / std::numbers::pi_v<float> * height));
    return image[static_cast<std::size_t>(y) * width + x];
  }

  bool empty() const { return image.empty() && (constant == 0.0f).all(); }

  /// A direction uniform over the sphere, in double.
  static Eigen::Vector3d direction(double a, double b) {
    const double z = 1.0 - 2.0 * a, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * std::numbers::pi * b;
    return {r * std::cos(phi), r * std::sin(phi), z};
  }

  LightSample sample(double a, double b) const {
    const Eigen::Vector3f d = direction(a, b).cast<float>();
    return {d, std::numeric_limits<float>::infinity(), radiance(d) * (4.0f * std::numbers::pi_v<float>)};
  }
};

struct Lights {
  std::vector<Sun> suns;
  std::vector<QuadLight> quads;
  Environment environment;
};

}  // namespace rice::shading
