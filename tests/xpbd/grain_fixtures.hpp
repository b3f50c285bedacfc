// A grain-sized body for the contact tests, without the grains module: a 7 × 3 × 2 mm box
// (tet mesh) with ten collision spheres of radius 1 mm in two rows along its length, so the
// sphere union spans the box. Lying flat, its lowest point is 1 mm below the sphere centres.
#pragma once

#include <algorithm>
#include <cmath>

#include "xpbd/body.hpp"
#include "xpbd/model.hpp"

namespace rice::xpbd::test_support {

constexpr double kGrainLength = 7e-3, kGrainWidth = 3e-3, kGrainThickness = 2e-3;
constexpr double kGrainDensity = 1.1e3;

/// The box mesh with its lower corner at `corner`, and its spheres.
inline TetMesh grain_mesh(const Vec3& corner) {
  TetMesh mesh = make_box_tet_mesh(Vec3(kGrainLength, kGrainWidth, kGrainThickness), 4, 2, 1);
  mesh.V.rowwise() += corner.transpose();
  return mesh;
}

inline SphereSet grain_spheres(const Vec3& corner) {
  const double r = 0.5 * kGrainThickness;
  SphereSet spheres{Positions(10, 3), Eigen::VectorXd::Constant(10, r)};
  for (int k = 0; k < 5; ++k)
    for (int row = 0; row < 2; ++row)
      spheres.centres.row(2 * k + row) =
          corner.transpose() + Eigen::RowVector3d(r + k * (kGrainLength - 2 * r) / 4.0,
                                                  r + row * (kGrainWidth - 2 * r), r);
  return spheres;
}

/// Adds one grain, rigid or soft (E = 50 kPa, ν = 0.3), its lower corner at `corner`.
inline int add_grain(Model& model, BodyKind kind, const Vec3& corner, double young = 5e4) {
  if (kind == BodyKind::kRigid) return add_rigid_body(model, grain_mesh(corner), kGrainDensity, grain_spheres(corner));
  return add_soft_body(model, grain_mesh(corner), kGrainDensity, lame_from_young_poisson(young, 0.3), 0.0,
                       grain_spheres(corner));
}

/// Lowest point of body b's sphere union (radii as they are now, sphere_radius).
inline double lowest_point(const Model& model, int b) {
  double lowest = INFINITY;
  for (int s = 0; s < model.bodies[b].sphere_count(); ++s)
    lowest = std::min(lowest, sphere_centre(model, model.bodies[b], s).z() - sphere_radius(model, model.bodies[b], s));
  return lowest;
}

/// Centre of mass of body b.
inline Vec3 body_centre(const Model& model, int b) { return xpbd::body_centre(model, model.bodies[b]); }

/// Total linear momentum of bodies and free particles.
inline Vec3 linear_momentum(const Model& model) {
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < model.particles.size(); ++i)
    if (model.particles.w[i] > 0.0) p += model.particles.v.row(i).transpose() / model.particles.w[i];
  for (const RigidBody& b : model.rigid_bodies)
    if (b.inverse_mass > 0.0) p += b.v / b.inverse_mass;
  return p;
}

/// Total mass of bodies and free particles, the weights of linear_momentum.
inline double total_mass(const Model& model) {
  double m = 0.0;
  for (int i = 0; i < model.particles.size(); ++i)
    if (model.particles.w[i] > 0.0) m += 1.0 / model.particles.w[i];
  for (const RigidBody& b : model.rigid_bodies)
    if (b.inverse_mass > 0.0) m += 1.0 / b.inverse_mass;
  return m;
}

/// A collider at rest.
inline Collider half_space(const Vec3& normal, double offset, double mu_s, double mu_k) {
  Collider c;
  c.shape = ColliderShape::kHalfSpace;
  c.motion[0].rotation = Quat::FromTwoVectors(Vec3::UnitZ(), normal);
  c.motion[0].translation = offset * normal;
  c.static_friction = mu_s;
  c.dynamic_friction = mu_k;
  return c;
}

/// A square box open at the top, 2 × `half_width` across: a floor at z = 0 (μ_s 0.5, μ_k 0.4)
/// and four walls (0.3, 0.2), as colliders.
inline void add_open_box(Model& model, double half_width) {
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  for (const Vec3& n : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)})
    model.colliders.push_back(half_space(n, -half_width, 0.3, 0.2));
}

}  // namespace rice::xpbd::test_support
