// Barrier contact through soft bodies' collision spheres; see sphere_contact_form.hpp.
#include "fem_reference/sphere_contact_form.hpp"

#include <stdexcept>
#include <string>

#include "xpbd/body.hpp"

namespace rice::fem {

using xpbd::Mat3;
using xpbd::Vec3;

namespace {

void require_valid(const BarrierSettings& s) {
  if (!(s.activation_distance > 0.0) || !(s.stiffness > 0.0) || !std::isfinite(s.activation_distance) ||
      !std::isfinite(s.stiffness))
    throw std::invalid_argument("reference solver: the sphere contact barrier needs a positive, finite d-hat and stiffness");
}

/// c = Σ_k w_k x_k from a local vector holding the four corners from `offset` on.
template <class Local>
Vec3 centre(const Local& x, const Eigen::Vector4d& w, int offset) {
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < 4; ++k) c += w[k] * x.template segment<3>(offset + 3 * k);
  return c;
}

/// The most a step dx moves a sphere's centre: Σ_k |w_k| ‖dx_k‖.
/// Σ_k w_k p_k over sphere s's corners: its centre for positions, its motion for a step.
Vec3 embedded_point(const EmbeddedSphere& s, const Positions& p) {
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < 4; ++k) sum += s.weights[k] * p.row(s.particles[k]).transpose();
  return sum;
}

void update_radii(const xpbd::Model& model, std::vector<EmbeddedSphere>& spheres) {
  const std::vector<EmbeddedSphere> now = embedded_spheres(model);
  for (size_t s = 0; s < spheres.size(); ++s) spheres[s].radius = now[s].radius;
}

}  // namespace

std::vector<EmbeddedSphere> embedded_spheres(const xpbd::Model& model, std::vector<int>* body_of) {
  std::vector<EmbeddedSphere> spheres;
  if (body_of) body_of->clear();
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const xpbd::Body& body = model.bodies[b];
    if (body.kind != xpbd::BodyKind::kSoft) continue;
    for (int s = 0; s < body.sphere_count(); ++s) {
      spheres.push_back({body.anchors[s].particles, body.anchors[s].weights, xpbd::sphere_radius(model, body, s)});
      if (body_of) body_of->push_back(static_cast<int>(b));
    }
  }
  return spheres;
}

// ---- sphere pairs ----

SpherePairContactForm::SpherePairContactForm(const xpbd::Model& model, const BarrierSettings& settings)
    : settings_(settings) {
  require_valid(settings);
  spheres_ = embedded_spheres(model, &body_of_);
  for (int a = 0; a < static_cast<int>(spheres_.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(spheres_.size()); ++b)
      if (body_of_[a] != body_of_[b]) pairs_.push_back({a, b});
}

void SpherePairContactForm::set_radii(const xpbd::Model& model) { update_radii(model, spheres_); }

SpherePairContactForm::Particles SpherePairContactForm::element_particles(int e) const {
  const auto& a = spheres_[pairs_[e][0]].particles;
  const auto& b = spheres_[pairs_[e][1]].particles;
  return {a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]};
}

SpherePairContactForm::Gap SpherePairContactForm::gap(int e, const LocalVector& x) const {
  const EmbeddedSphere& a = spheres_[pairs_[e][0]];
  const EmbeddedSphere& b = spheres_[pairs_[e][1]];
  const Vec3 r = centre(x, a.weights, 0) - centre(x, b.weights, 12);
  const double length = r.norm();
  return {length - a.radius - b.radius, length > 0.0 ? Vec3(r / length) : Vec3::UnitZ(), length};
}

double SpherePairContactForm::element_value(int e, const LocalVector& x) const {
  return settings_.stiffness * ipc_barrier(gap(e, x).d, settings_.activation_distance).value;
}

SpherePairContactForm::LocalVector SpherePairContactForm::element_gradient(int e, const LocalVector& x) const {
  const Gap g = gap(e, x);
  const double first = settings_.stiffness * ipc_barrier(g.d, settings_.activation_distance).first;
  LocalVector gradient = LocalVector::Zero();
  if (first == 0.0) return gradient;
  const Eigen::Vector4d& wa = spheres_[pairs_[e][0]].weights;
  const Eigen::Vector4d& wb = spheres_[pairs_[e][1]].weights;
  for (int k = 0; k < 4; ++k) {
    gradient.segment<3>(3 * k) = first * wa[k] * g.normal;
    gradient.segment<3>(12 + 3 * k) = -first * wb[k] * g.normal;
  }
  return gradient;
}

SpherePairContactForm::LocalMatrix SpherePairContactForm::element_hessian(int e, const LocalVector& x,
                                                                         bool project) const {
  const Gap g = gap(e, x);
  const BarrierValue b = ipc_barrier(g.d, settings_.activation_distance);
  LocalMatrix H = LocalMatrix::Zero();
  if (b.second == 0.0) return H;
  // d depends on x only through r = c_a − c_b = J x, J = [w_a ⊗ I, −w_b ⊗ I]:
  // ∇²(κ b) = κ Jᵀ (b'' n nᵀ + b' (I − n nᵀ)/‖r‖) J.
  const Mat3 nn = g.normal * g.normal.transpose();
  Mat3 inner = b.second * nn + b.first * (Mat3::Identity() - nn) / g.length;
  // b' < 0: the curvature term is negative semi-definite; projected, only b'' n nᵀ (≥ 0) stays.
  if (project) inner = b.second * nn;
  Eigen::Matrix<double, 8, 1> signed_weights;
  signed_weights << spheres_[pairs_[e][0]].weights, -spheres_[pairs_[e][1]].weights;
  for (int j = 0; j < 8; ++j)
    for (int k = 0; k < 8; ++k)
      H.block<3, 3>(3 * j, 3 * k) = settings_.stiffness * signed_weights[j] * signed_weights[k] * inner;
  return H;
}

double SpherePairContactForm::max_step(const Positions& x, const Positions& dx) const {
  // The centres move linearly in the step t: r(t) = r + t q, q the difference of their
  // motions. The step ends where ‖r(t)‖ first falls to R + d/10 (R = r_a + r_b, d the gap
  // now): the smaller root of ‖r + t q‖² = (R + d/10)². Exact, so a sphere sliding around
  // another (q across n) is not held back, as a bound on ‖q‖ alone would hold it.
  double step = 1.0;
  for (int e = 0; e < element_count(); ++e) {
    const EmbeddedSphere& a = spheres_[pairs_[e][0]];
    const EmbeddedSphere& b = spheres_[pairs_[e][1]];
    const Vec3 q = embedded_point(a, dx) - embedded_point(b, dx);
    const Vec3 r = embedded_point(a, x) - embedded_point(b, x);
    const double qq = q.squaredNorm(), rq = r.dot(q);
    if (qq == 0.0 || rq >= 0.0) continue;  // not approaching
    const double length = r.norm();
    const double target = a.radius + b.radius + 0.1 * (length - a.radius - b.radius);
    const double discriminant = rq * rq - qq * (length * length - target * target);
    if (discriminant < 0.0) continue;  // passes by
    step = std::min(step, std::max((-rq - std::sqrt(discriminant)) / qq, 0.0));
  }
  return step;
}

Vec3 SpherePairContactForm::force_on_body(const Positions& x, int body) const {
  Vec3 force = Vec3::Zero();
  for (int e = 0; e < element_count(); ++e) {
    const int side = body_of_[pairs_[e][0]] == body ? 0 : body_of_[pairs_[e][1]] == body ? 1 : -1;
    if (side < 0) continue;
    const LocalVector g = element_gradient(e, gather(x, e));
    for (int k = 0; k < 4; ++k) force -= g.segment<3>(12 * side + 3 * k);
  }
  return force;
}

// ---- spheres against half-spaces ----

SpherePlaneContactForm::SpherePlaneContactForm(const xpbd::Model& model, const BarrierSettings& settings)
    : settings_(settings), spheres_(embedded_spheres(model)) {
  require_valid(settings);
  for (size_t c = 0; c < model.colliders.size(); ++c) {
    if (model.colliders[c].shape != xpbd::ColliderShape::kHalfSpace)
      throw std::invalid_argument("reference solver: collider " + std::to_string(c) +
                                  " is not a half-space; collision spheres meet only half-spaces there");
    planes_.push_back({&model.colliders[c], Vec3::UnitZ(), 0.0});
  }
  for (int s = 0; s < static_cast<int>(spheres_.size()); ++s)
    for (int p = 0; p < static_cast<int>(planes_.size()); ++p) elements_.push_back({s, p});
  set_time(0.0);
}

void SpherePlaneContactForm::set_radii(const xpbd::Model& model) { update_radii(model, spheres_); }

void SpherePlaneContactForm::set_time(double t) {
  for (Plane& plane : planes_) {
    const xpbd::ColliderKeyframe pose = xpbd::collider_pose(*plane.collider, t);
    plane.normal = pose.rotation * Vec3::UnitZ();
    plane.offset = plane.normal.dot(pose.translation);
  }
}

double SpherePlaneContactForm::gap(int e, const LocalVector& x) const {
  const EmbeddedSphere& s = spheres_[elements_[e][0]];
  const Plane& plane = planes_[elements_[e][1]];
  return plane.normal.dot(centre(x, s.weights, 0)) - plane.offset - s.radius;
}

double SpherePlaneContactForm::element_value(int e, const LocalVector& x) const {
  return settings_.stiffness * ipc_barrier(gap(e, x), settings_.activation_distance).value;
}

SpherePlaneContactForm::LocalVector SpherePlaneContactForm::element_gradient(int e, const LocalVector& x) const {
  const double first = settings_.stiffness * ipc_barrier(gap(e, x), settings_.activation_distance).first;
  LocalVector gradient;
  for (int k = 0; k < 4; ++k)
    gradient.segment<3>(3 * k) = first * spheres_[elements_[e][0]].weights[k] * planes_[elements_[e][1]].normal;
  return gradient;
}

SpherePlaneContactForm::LocalMatrix SpherePlaneContactForm::element_hessian(int e, const LocalVector& x,
                                                                           bool /*project*/) const {
  // d is affine in x: ∇²(κ b) = κ b'' ∇d ∇dᵀ, positive semi-definite as it is.
  const double second = settings_.stiffness * ipc_barrier(gap(e, x), settings_.activation_distance).second;
  LocalVector grad_d;
  for (int k = 0; k < 4; ++k)
    grad_d.segment<3>(3 * k) = spheres_[elements_[e][0]].weights[k] * planes_[elements_[e][1]].normal;
  return second * grad_d * grad_d.transpose();
}

double SpherePlaneContactForm::max_step(const Positions& x, const Positions& dx) const {
  double step = 1.0;
  for (int e = 0; e < element_count(); ++e) {
    const EmbeddedSphere& s = spheres_[elements_[e][0]];
    const double approach = -planes_[elements_[e][1]].normal.dot(embedded_point(s, dx));
    if (!(approach > 0.0)) continue;
    const double d = gap(e, gather(x, e));
    if (0.9 * d < step * approach) step = std::max(0.9 * d / approach, 0.0);
  }
  return step;
}

Vec3 SpherePlaneContactForm::force_from_plane(const Positions& x, int plane) const {
  Vec3 force = Vec3::Zero();
  for (int e = 0; e < element_count(); ++e) {
    if (elements_[e][1] != plane) continue;
    const LocalVector g = element_gradient(e, gather(x, e));
    for (int k = 0; k < 4; ++k) force -= g.segment<3>(3 * k);
  }
  return force;
}

}  // namespace rice::fem
