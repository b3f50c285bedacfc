// The IPC barrier against planes and spheres; see barrier_contact_form.hpp.
#include "fem_reference/barrier_contact_form.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rice::fem {

using xpbd::Mat3;
using xpbd::Vec3;

BarrierValue ipc_barrier(double d, double dhat) {
  if (d >= dhat) return {0.0, 0.0, 0.0};
  if (!(d > 0.0)) {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, -inf, inf};
  }
  const double gap = d - dhat, log_ratio = std::log(d / dhat);
  return {-gap * gap * log_ratio,                                          // b
          -2.0 * gap * log_ratio - gap * gap / d,                          // b'
          -2.0 * log_ratio - 4.0 * gap / d + gap * gap / (d * d)};         // b''
}

BarrierContactForm::BarrierContactForm(const xpbd::Model& model, const BarrierSettings& settings)
    : settings_(settings) {
  if (!(settings.activation_distance > 0.0) || !(settings.stiffness > 0.0) ||
      !std::isfinite(settings.activation_distance) || !std::isfinite(settings.stiffness))
    throw std::invalid_argument("reference solver: the contact barrier needs a positive, finite d-hat and stiffness");
  std::vector<char> in_sphere_body(static_cast<size_t>(model.particles.size()), 0);
  for (const xpbd::Body& body : model.bodies)
    if (body.kind == xpbd::BodyKind::kSoft && body.sphere_count() > 0)
      std::fill_n(in_sphere_body.begin() + body.first_particle, body.particle_count, 1);
  for (int i = 0; i < model.particles.size(); ++i)
    if (model.particles.w[i] > 0.0) {
      particles_.push_back(i);
      meets_colliders_.push_back(!in_sphere_body[i]);
    }
  if (model.ground) obstacles_.push_back({nullptr, false, model.ground->normal.normalized(), model.ground->offset});
  for (size_t c = 0; c < model.colliders.size(); ++c) {
    const xpbd::Collider& collider = model.colliders[c];
    if (collider.shape != xpbd::ColliderShape::kHalfSpace && collider.shape != xpbd::ColliderShape::kSphere)
      throw std::invalid_argument("reference solver: collider " + std::to_string(c) +
                                  " is not a half-space or a sphere; its contact barrier knows only those");
    Obstacle o;
    o.collider = &collider;
    o.sphere = collider.shape == xpbd::ColliderShape::kSphere;
    o.radius = collider.radius;
    obstacles_.push_back(o);
  }
  set_time(0.0);
}

void BarrierContactForm::set_time(double t) {
  for (Obstacle& o : obstacles_) {
    if (!o.collider) continue;
    const xpbd::ColliderKeyframe pose = xpbd::collider_pose(*o.collider, t);
    o.normal = pose.rotation * Vec3::UnitZ();
    o.offset = o.normal.dot(pose.translation);
    o.centre = pose.translation;
  }
}

BarrierContactForm::Distance BarrierContactForm::distance(const Obstacle& o, const Vec3& p) {
  if (!o.sphere) return {o.normal.dot(p) - o.offset, o.normal, Mat3::Zero()};
  const Vec3 r = p - o.centre;
  const double length = r.norm();
  const Vec3 n = length > 0.0 ? Vec3(r / length) : Vec3::UnitZ();
  const Mat3 hessian = length > 0.0 ? Mat3((Mat3::Identity() - n * n.transpose()) / length) : Mat3::Zero();
  return {length - o.radius, n, hessian};
}

double BarrierContactForm::element_value(int e, const LocalVector& x) const {
  double sum = 0.0;
  for (const Obstacle& o : obstacles_)
    if (acts_on(o, e)) sum += ipc_barrier(distance(o, x).d, settings_.activation_distance).value;
  return settings_.stiffness * sum;
}

BarrierContactForm::LocalVector BarrierContactForm::element_gradient(int e, const LocalVector& x) const {
  LocalVector g = LocalVector::Zero();
  for (const Obstacle& o : obstacles_) {
    if (!acts_on(o, e)) continue;
    const Distance d = distance(o, x);
    g += ipc_barrier(d.d, settings_.activation_distance).first * d.gradient;
  }
  return settings_.stiffness * g;
}

BarrierContactForm::LocalMatrix BarrierContactForm::element_hessian(int e, const LocalVector& x, bool project) const {
  // ∇²[b(d)] = b'' ∇d ∇dᵀ + b' ∇²d; b'' > 0 below d̂, b' < 0, ∇²d ⪰ 0 for a sphere seen from
  // outside, so only the curvature term can be indefinite.
  LocalMatrix H = LocalMatrix::Zero();
  for (const Obstacle& o : obstacles_) {
    if (!acts_on(o, e)) continue;
    const Distance d = distance(o, x);
    const BarrierValue b = ipc_barrier(d.d, settings_.activation_distance);
    if (b.second == 0.0) continue;
    H += b.second * d.gradient * d.gradient.transpose() + b.first * d.hessian;
  }
  H *= settings_.stiffness;
  return project ? project_to_psd(H) : H;
}

double BarrierContactForm::max_step(const Positions& x, const Positions& dx) const {
  double step = 1.0;
  for (int e = 0; e < element_count(); ++e) {
    const int i = particles_[e];
    const double move = dx.row(i).norm();
    if (move == 0.0) continue;
    for (const Obstacle& o : obstacles_) {
      if (!acts_on(o, e)) continue;
      const double d = distance(o, x.row(i).transpose()).d;
      // A plane is approached at the normal speed; a sphere's distance is 1-Lipschitz.
      const double approach = o.sphere ? move : -o.normal.dot(dx.row(i).transpose());
      if (0.9 * d < step * approach) step = std::max(0.9 * d / approach, 0.0);
    }
  }
  return step;
}

Vec3 BarrierContactForm::contact_force(const Positions& x, int obstacle) const {
  Vec3 force = Vec3::Zero();
  const Obstacle& o = obstacles_[obstacle];
  for (int e = 0; e < element_count(); ++e) {
    if (!acts_on(o, e)) continue;
    const Distance d = distance(o, x.row(particles_[e]).transpose());
    force -= settings_.stiffness * ipc_barrier(d.d, settings_.activation_distance).first * d.gradient;
  }
  return force;
}

}  // namespace rice::fem
