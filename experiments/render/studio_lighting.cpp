// The food photographer's set; see studio_lighting.hpp.
#include "experiments/render/studio_lighting.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "experiments/render/scene_pieces.hpp"

namespace rice::experiments {
namespace {

const shading::Color kStudioWarmWhite(1.0f, 0.92f, 0.82f);  // about 4000 K, normalised to red

/// A square light of side `side` centred at `centre`, facing `target`, with the radiance L that
/// gives `irradiance` E at the target on a surface facing it. On the axis of a square of half
/// side a at distance d, with X = a/d, the four quarters' form factors (Howell's catalogue,
/// configuration C-11, a differential area to a parallel rectangle from a corner) sum to
///   E = 4 L X/√(1+X²) · atan(X/√(1+X²)).
shading::QuadLight softbox(const Eigen::Vector3d& centre, const Eigen::Vector3d& target, double side, double irradiance,
                           const shading::Color& colour) {
  const Eigen::Vector3d n = (target - centre).normalized();  // the side it shines to
  const Eigen::Vector3d t1 = n.cross(Eigen::Vector3d::UnitZ()).normalized(), t2 = t1.cross(n);  // t2 × t1 = n
  const double X = 0.5 * side / (target - centre).norm(), q = X / std::sqrt(1.0 + X * X);
  const double e_per_radiance = 4.0 * q * std::atan(q);
  shading::QuadLight quad;
  quad.corner = (centre - 0.5 * side * (t1 + t2)).cast<float>();
  quad.edge_u = (side * t1).cast<float>();
  quad.edge_v = (side * t2).cast<float>();
  quad.radiance = colour * static_cast<float>(irradiance / e_per_radiance);
  return quad;
}

/// A vertical rectangle through `base` (its bottom edge's middle), across `across` (unit,
/// horizontal), `width` wide and `height` tall, facing `facing` (unit, horizontal).
void add_wall(shading::RenderScene& scene, const Eigen::Vector3d& base, const Eigen::Vector3d& across,
              const Eigen::Vector3d& facing, double width, double height, int material) {
  shading::MeshVertices V(4, 3);
  const Eigen::Vector3d a = base - 0.5 * width * across, b = base + 0.5 * width * across;
  V.row(0) = a.transpose();
  V.row(1) = b.transpose();
  V.row(2) = (b + height * Eigen::Vector3d::UnitZ()).transpose();
  V.row(3) = (a + height * Eigen::Vector3d::UnitZ()).transpose();
  shading::MeshTriangles F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  if ((b - a).cross(Eigen::Vector3d::UnitZ()).dot(facing) < 0.0) F << 0, 2, 1, 0, 3, 2;  // outward towards `facing`
  scene.add_instance(scene.add_prototype(V, F), Eigen::Affine3d::Identity(), material);
}

double subject_size(const Eigen::AlignedBox3d& subject) { return std::max(subject.diagonal().norm(), 1e-3); }

/// The horizontal unit vector from the subject's centre towards the eye.
Eigen::Vector3d towards_eye(const Eigen::AlignedBox3d& subject, const Eigen::Vector3d& eye) {
  Eigen::Vector3d d = eye - subject.center();
  d.z() = 0.0;
  return d.norm() > 0.0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitX();
}

}  // namespace

shading::Lights studio_lights(const Eigen::AlignedBox3d& subject, const Eigen::Vector3d& eye,
                              const StudioLighting& lighting) {
  const Eigen::Vector3d c = subject.center();
  const double size = subject_size(subject), distance = 3.0 * size, side = 2.0 * size;
  const Eigen::Vector3d e = towards_eye(subject, eye);
  const double eye_azimuth = std::atan2(e.y(), e.x()) * 180.0 / std::numbers::pi;  // [°]
  const auto at = [&](double elevation, double azimuth) -> Eigen::Vector3d {
    return c + distance * direction_from(elevation, eye_azimuth + azimuth);
  };
  shading::Lights lights;
  lights.quads.push_back(softbox(at(lighting.key_elevation_degrees, lighting.key_azimuth_degrees), c, side,
                                 lighting.key_irradiance, kStudioWarmWhite));
  lights.quads.push_back(softbox(at(20.0, -45.0), c, side,
                                 lighting.fill_ratio * lighting.key_irradiance, kStudioWarmWhite));
  lights.environment.constant = kStudioWarmWhite * static_cast<float>(lighting.room_radiance);
  return lights;
}

void add_studio_set(shading::RenderScene& scene, const Eigen::AlignedBox3d& subject, const Eigen::Vector3d& eye,
                    int table, int backdrop) {
  const Eigen::Vector3d c = subject.center(), back = -towards_eye(subject, eye);
  const double size = subject_size(subject), z = subject.min().z() - 1e-6, half = 4.0 * size;
  add_ground(scene, c.x() - half, c.y() - half, c.x() + half, c.y() + half, z, table);
  add_wall(scene, Eigen::Vector3d(c.x(), c.y(), z) + 1.5 * size * back, back.cross(Eigen::Vector3d::UnitZ()), -back,
           2.0 * half, 2.0 * half, backdrop);
}

}  // namespace rice::experiments
