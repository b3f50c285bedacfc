// Smooth dielectric interface: Fresnel reflectance for unpolarised light and Snell
// refraction. η is the refractive index of the side the light goes into over that of the
// side it comes from.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace rice::shading {

/// Fraction reflected for light meeting the interface at cos θ_i = `cos_incident` (> 0,
/// measured from the normal on its own side); 1 under total internal reflection.
inline double fresnel_reflectance(double cos_incident, double eta) {
  const double cos_i = std::clamp(std::abs(cos_incident), 0.0, 1.0);
  const double sin_t2 = (1.0 - cos_i * cos_i) / (eta * eta);
  if (sin_t2 >= 1.0) return 1.0;
  const double cos_t = std::sqrt(1.0 - sin_t2);
  const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

/// Direction after refraction of unit `d` at a surface of unit normal `n` (either side);
/// the caller has ruled out total internal reflection.
inline Eigen::Vector3d refract(const Eigen::Vector3d& d, const Eigen::Vector3d& n, double eta) {
  const Eigen::Vector3d facing = d.dot(n) < 0.0 ? n : Eigen::Vector3d(-n);  // against d
  const double cos_i = -d.dot(facing);
  const double cos_t = std::sqrt(std::max(0.0, 1.0 - (1.0 - cos_i * cos_i) / (eta * eta)));
  return (d / eta + (cos_i / eta - cos_t) * facing).normalized();
}

}  // namespace rice::shading
