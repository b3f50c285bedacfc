// Building soft and rigid bodies and the four contact operations on them; see body.hpp.
#include "xpbd/body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

#include "xpbd/model.hpp"
#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {
namespace {

void require_spheres(const SphereSet& spheres, const char* who) {
  if (spheres.centres.rows() != spheres.radii.size() || spheres.radii.size() == 0)
    throw std::invalid_argument(std::string(who) + ": need one radius per sphere centre and at least one sphere");
  for (int s = 0; s < spheres.radii.size(); ++s)
    if (!(spheres.radii[s] > 0.0) || !std::isfinite(spheres.radii[s]) || !spheres.centres.row(s).allFinite())
      throw std::invalid_argument(std::string(who) + ": sphere " + std::to_string(s) +
                                  " needs a finite centre and a positive finite radius");
}

/// Barycentric weights of p in the tet, and how far outside it p lies (0 inside): the most
/// negative weight, negated.
Eigen::Vector4d barycentric(const Vec12& corners, const Vec3& p, double* outside) {
  const Vec3 x0 = corners.segment<3>(0);
  const Vec3 b = edge_matrix(corners).inverse() * (p - x0);
  const Eigen::Vector4d w(1.0 - b.sum(), b.x(), b.y(), b.z());
  *outside = std::max(0.0, -w.minCoeff());
  return w;
}

}  // namespace

int add_rigid_body(Model& model, const TetMesh& mesh, double density, const SphereSet& spheres) {
  require_spheres(spheres, "add_rigid_body");
  const RigidBody rigid = make_rigid_body(mesh.V, mesh.T, density);
  Body body;
  body.kind = BodyKind::kRigid;
  body.rigid_body = static_cast<int>(model.rigid_bodies.size());
  for (int s = 0; s < spheres.radii.size(); ++s) {
    body.local_centres.push_back(rigid.to_local(spheres.centres.row(s).transpose()));
    body.radii.push_back(spheres.radii[s]);
  }
  model.rigid_bodies.push_back(rigid);
  model.bodies.push_back(std::move(body));
  return static_cast<int>(model.bodies.size()) - 1;
}

int add_soft_body(Model& model, const TetMesh& mesh, double density, const LameParameters& material,
                  double rayleigh_time, const SphereSet& spheres, double strain_rate_time,
                  TetMaterial tet_material) {
  require_spheres(spheres, "add_soft_body");
  // Build the body alone, then append it with its particle indices shifted.
  Model single;
  single.particles = make_particles(mesh, density);
  add_neo_hookean_tets(single, mesh, material, rayleigh_time, strain_rate_time, tet_material);
  const int offset = model.particles.size();
  Particles& p = model.particles;
  const int total = offset + single.particles.size();
  p.x.conservativeResize(total, 3);
  p.v.conservativeResize(total, 3);
  p.w.conservativeResize(total);
  p.x.bottomRows(single.particles.size()) = single.particles.x;
  p.v.bottomRows(single.particles.size()) = single.particles.v;
  p.w.tail(single.particles.size()) = single.particles.w;
  for (NeoHookeanTet tet : single.neo_hookean) {
    for (int& i : tet.particles) i += offset;
    model.neo_hookean.push_back(tet);
  }
  Body body;
  body.kind = BodyKind::kSoft;
  body.first_particle = offset;
  body.particle_count = single.particles.size();
  for (int s = 0; s < spheres.radii.size(); ++s) {
    // The tet holding the centre, or the one it lies least outside.
    const Vec3 centre = spheres.centres.row(s).transpose();
    double best = std::numeric_limits<double>::infinity();
    int holder = 0;
    Eigen::Vector4d weights;
    for (int t = 0; t < mesh.T.rows() && best > 0.0; ++t) {
      double outside;
      const Eigen::Vector4d w = barycentric(tet_positions(mesh.V, mesh.T, t), centre, &outside);
      if (outside < best) best = outside, holder = t, weights = w;
    }
    body.anchors.push_back({{mesh.T(holder, 0) + offset, mesh.T(holder, 1) + offset, mesh.T(holder, 2) + offset,
                             mesh.T(holder, 3) + offset},
                            weights});
    body.anchor_tets.push_back(static_cast<int>(model.neo_hookean.size() - single.neo_hookean.size()) + holder);
    body.radii.push_back(spheres.radii[s]);
  }
  model.bodies.push_back(std::move(body));
  return static_cast<int>(model.bodies.size()) - 1;
}

std::vector<int> soft_body_of_particle(const Model& model) {
  std::vector<int> owner(model.particles.size(), -1);
  for (size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].kind == BodyKind::kSoft)
      std::fill_n(owner.begin() + model.bodies[b].first_particle, model.bodies[b].particle_count, static_cast<int>(b));
  return owner;
}

Vec3 body_centre(const Model& model, const Body& body) {
  if (body.kind == BodyKind::kRigid) return model.rigid_bodies[body.rigid_body].x;
  const Eigen::VectorXd masses = model.particles.w.segment(body.first_particle, body.particle_count).cwiseInverse();
  return model.particles.x.middleRows(body.first_particle, body.particle_count).transpose() * masses / masses.sum();
}

double reach(const Body& body) {
  double r = 0.0;
  for (int s = 0; s < body.sphere_count(); ++s) r = std::max(r, body.local_centres[s].norm() + body.radii[s]);
  return r;
}

Vec3 sphere_centre(const Model& model, const Body& body, int s) {
  if (body.kind == BodyKind::kRigid) return model.rigid_bodies[body.rigid_body].world_point(body.local_centres[s]);
  return body.anchors[s].at(model.particles.x);
}

double sphere_radius(const Model& model, const Body& body, int s) {
  if (body.kind == BodyKind::kRigid) return body.radii[s];
  const NeoHookeanTet& tet = model.neo_hookean[body.anchor_tets[s]];
  const auto& x = model.particles.x;
  const auto corner = [&](int k) -> Vec3 { return x.row(tet.particles[k]).transpose(); };
  const Mat3 F = edge_matrix(corner(0), corner(1), corner(2), corner(3)) * tet.Dm_inv;
  // Turned inside out (det F ≤ 0), the signed smallest stretch is ≤ 0: the sphere shrinks to its
  // centre. Its contacts, with the centre placed through a tangled tet, held a grain's folded tets
  // against its neighbours (one jittered folded for the last 25 frames of the rice cooker's
  // tenth, where alone it unfolded within 5 frames).
  if (F.determinant() <= 0.0) return 0.0;
  const Mat3 C = F.transpose() * F;
  // Stretched every way (σ_min > 1: FᵀF − I positive definite, Sylvester's leading minors),
  // the sphere keeps its rest radius. This test costs a tenth of the eigenvalues below, whose
  // atan2, cos and sin were 10% of a soft shari's run (the run is 2% faster with it: most
  // spheres of a resting pile are squeezed a little).
  const Mat3 M = C - Mat3::Identity();
  if (M(0, 0) > 0.0 && M(0, 0) * M(1, 1) - M(0, 1) * M(0, 1) > 0.0 && M.determinant() > 0.0) return body.radii[s];
  // σ_min² is the smallest eigenvalue of FᵀF (closed form for a symmetric 3 × 3).
  Eigen::SelfAdjointEigenSolver<Mat3> eigen;
  eigen.computeDirect(C, Eigen::EigenvaluesOnly);
  return body.radii[s] * std::min(1.0, std::sqrt(std::max(0.0, eigen.eigenvalues()(0))));
}

Vec3 previous_point(const Model& model, const Body& body, int s, const Vec3& point, const Positions& x_previous) {
  if (body.kind == BodyKind::kRigid) {
    const RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    return rigid.previous_world_point(rigid.to_local(point));
  }
  // The point moves with the embedding of the sphere's centre.
  return point - body.anchors[s].displacement(model.particles.x, x_previous);
}

double inverse_mass_at(const Model& model, const Body& body, int s, const Vec3& point, const Vec3& n) {
  if (body.asleep) return 0.0;
  if (body.kind == BodyKind::kRigid) {
    const RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    return generalized_inverse_mass(rigid, point - rigid.x, n);
  }
  return body.anchors[s].inverse_mass(model.particles.w);
}

void apply_impulse_at(Model& model, const Body& body, int s, const Vec3& point, const Vec3& p) {
  if (body.asleep) return;
  if (body.kind == BodyKind::kRigid) {
    RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    apply_positional_impulse(rigid, point - rigid.x, p);
    return;
  }
  body.anchors[s].apply(model.particles.x, model.particles.w, p);
}

Vec3 material_coordinates(const Model& model, const Body& body, int s, const Vec3& point, const Positions* x_previous) {
  if (body.kind == BodyKind::kRigid) {
    const RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    return x_previous ? rigid.to_previous_local(point) : rigid.to_local(point);
  }
  return point - body.anchors[s].at(x_previous ? *x_previous : model.particles.x);
}

Vec3 material_point(const Model& model, const Body& body, int s, const Vec3& coordinates) {
  if (body.kind == BodyKind::kRigid) return model.rigid_bodies[body.rigid_body].world_point(coordinates);
  return sphere_centre(model, body, s) + coordinates;
}

Vec3 velocity_at(const Model& model, const Body& body, int s, const Vec3& point) {
  if (body.kind == BodyKind::kRigid) {
    const RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    return rigid.v + rigid.omega.cross(point - rigid.x);
  }
  return body.anchors[s].at(model.particles.v);
}

void apply_velocity_impulse_at(Model& model, const Body& body, int s, const Vec3& point, const Vec3& p) {
  if (body.asleep) return;
  if (body.kind == BodyKind::kRigid) {
    RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    if (rigid.inverse_mass == 0.0) return;
    rigid.v += rigid.inverse_mass * p;
    rigid.omega += rigid.apply_inverse_inertia((point - rigid.x).cross(p));
    return;
  }
  body.anchors[s].apply(model.particles.v, model.particles.w, p);
}

}  // namespace rice::xpbd
