// Tessellated parametric grain surface (see base_shape.hpp for the formula).
#include "grains/base_shape.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rice::grains {
namespace {

// Surface point at (θ, φ) before the notch.
Vec3 profile_point(const GrainShape& shape, double theta, double phi) {
  const double u = std::cos(theta);
  const double s = std::pow(std::max(0.0, 1.0 - std::pow(std::abs(u), shape.tip_exponent)), 1.0 / shape.tip_exponent);
  const double c = std::cos(phi);
  const double side = c > 0.0 ? 1.0 + shape.asymmetry : 1.0 - shape.asymmetry;
  return {0.5 * shape.length * u, 0.5 * shape.width * side * s * c, 0.5 * shape.thickness * s * std::sin(phi)};
}

}  // namespace

SurfaceMesh make_base_shape(const GrainShape& shape, const BaseShapeResolution& resolution) {
  if (resolution.rings < 3 || resolution.segments < 3)
    throw std::invalid_argument("base shape: rings and segments must be >= 3");
  const int rings = resolution.rings, segments = resolution.segments;
  const int ring_vertices = (rings - 1) * segments;
  SurfaceMesh mesh;
  mesh.V.resize(ring_vertices + 2, 3);
  const double pi = std::numbers::pi;
  for (int j = 1; j < rings; ++j)
    for (int k = 0; k < segments; ++k)
      mesh.V.row((j - 1) * segments + k) = profile_point(shape, pi * j / rings, 2.0 * pi * k / segments);
  const int tip_plus = ring_vertices, tip_minus = ring_vertices + 1;
  mesh.V.row(tip_plus) = profile_point(shape, 0.0, 0.0);
  mesh.V.row(tip_minus) = profile_point(shape, pi, 0.0);

  // Embryo notch: radial pull towards the origin, Gaussian in the distance to its centre.
  if (shape.notch_depth > 0.0 && shape.notch_size > 0.0) {
    const Vec3 centre = profile_point(shape, std::acos(0.8), pi);
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
      const Vec3 p = mesh.V.row(v);
      const double pull = shape.notch_depth *
                          std::exp(-(p - centre).squaredNorm() / (2.0 * shape.notch_size * shape.notch_size));
      mesh.V.row(v) = p * std::max(0.1, 1.0 - pull / p.norm());
    }
  }

  // Faces: quads between rings split in two, fans at the tips; outward for θ growing
  // from +x and φ counter-clockwise about +x.
  mesh.F.resize(2 * segments * (rings - 1), 3);
  int f = 0;
  const auto vertex = [&](int j, int k) { return (j - 1) * segments + (k % segments); };
  for (int k = 0; k < segments; ++k) {
    mesh.F.row(f++) << tip_plus, vertex(1, k), vertex(1, k + 1);
    mesh.F.row(f++) << tip_minus, vertex(rings - 1, k + 1), vertex(rings - 1, k);
  }
  for (int j = 1; j + 1 < rings; ++j)
    for (int k = 0; k < segments; ++k) {
      mesh.F.row(f++) << vertex(j, k), vertex(j + 1, k), vertex(j + 1, k + 1);
      mesh.F.row(f++) << vertex(j, k), vertex(j + 1, k + 1), vertex(j, k + 1);
    }
  return mesh;
}

}  // namespace rice::grains
