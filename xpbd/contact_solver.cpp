// Broad phase, speculative contacts and their projection with friction; see contact_solver.hpp.
#include "xpbd/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "xpbd/broad_phase.hpp"
#include "xpbd/sleeping.hpp"

namespace rice::xpbd {
namespace {

Vec3 to_world(const ColliderKeyframe& pose, const Vec3& local) { return pose.translation + pose.rotation * local; }
Vec3 to_local(const ColliderKeyframe& pose, const Vec3& world) {
  return pose.rotation.conjugate() * (world - pose.translation);
}

/// How far any point of a body can move in `span` seconds, with leeway for what contacts
/// add: 1.5 (|v| + |ω| r_max) span + ½ |g| span² (soft: the fastest particle). A sleeping
/// body does not move.
double motion_bound(const Model& model, const Body& body, double span) {
  if (body.asleep) return 0.0;
  double speed = 0.0;
  if (body.kind == BodyKind::kRigid) {
    const RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    if (rigid.inverse_mass == 0.0) return 0.0;
    speed = rigid.v.norm() + rigid.omega.norm() * reach(body);
  } else {
    for (int i = body.first_particle; i < body.first_particle + body.particle_count; ++i)
      speed = std::max(speed, model.particles.v.row(i).norm());
  }
  return 1.5 * speed * span + 0.5 * model.gravity.norm() * span * span;
}

}  // namespace

ContactSolver::ContactSolver(Model& model) : model_(model) {
  const ContactSettings& s = model.contact;
  if (!(s.static_friction >= 0.0 && s.dynamic_friction >= 0.0 && s.dynamic_friction <= s.static_friction))
    throw std::invalid_argument("contact: need 0 <= dynamic friction <= static friction between grains");
  if (!(s.margin >= 0.0 && std::isfinite(s.margin))) throw std::invalid_argument("contact: margin must be >= 0");
  if (!(s.bond_compliance >= 0.0 && std::isfinite(s.bond_compliance)))
    throw std::invalid_argument("contact: bond compliance must be >= 0");
  if (!(s.bond_distance >= 0.0 && std::isfinite(s.bond_distance)))
    throw std::invalid_argument("contact: bond distance must be >= 0");
  if (s.cohesion) bonds_.emplace();
  sphere_offset_.assign(1, 0);
  for (const Body& body : model.bodies) sphere_offset_.push_back(sphere_offset_.back() + body.sphere_count());
  has_friction_ = s.static_friction > 0.0;
  for (size_t c = 0; c < model.colliders.size(); ++c) {
    validate(model.colliders[c], static_cast<int>(c));
    has_friction_ = has_friction_ || model.colliders[c].static_friction > 0.0;
  }
}

void ContactSolver::find_candidates(double time, double span) {
  const auto& bodies = model_.bodies;
  const double margin = model_.contact.margin;
  std::vector<double> pad(bodies.size());
  std::vector<Box> tight(bodies.size()), boxes(bodies.size());
  centre_now_.resize(sphere_offset_.back());
  for (size_t b = 0; b < bodies.size(); ++b) {
    pad[b] = motion_bound(model_, bodies[b], span) + margin;
    Box box{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
    for (int s = 0; s < bodies[b].sphere_count(); ++s) {
      const Vec3 c = centre_now_[sphere_offset_[b] + s] = sphere_centre(model_, bodies[b], s);
      box.lower = box.lower.cwiseMin(c - Vec3::Constant(bodies[b].radii[s]));
      box.upper = box.upper.cwiseMax(c + Vec3::Constant(bodies[b].radii[s]));
    }
    tight[b] = box;
    boxes[b] = {box.lower - Vec3::Constant(pad[b]), box.upper + Vec3::Constant(pad[b])};
  }
  const auto centre = [&](int b, int s) -> const Vec3& { return centre_now_[sphere_offset_[b] + s]; };
  const std::vector<std::pair<int, int>> pairs = overlapping_pairs(boxes);
  // A body that moved in the last step wakes the sleeping bodies its box reaches.
  for (const auto& [a, b] : pairs) {
    Body& body_a = model_.bodies[a];
    Body& body_b = model_.bodies[b];
    if (body_a.asleep && !body_b.asleep && body_b.moving) wake(body_a);
    if (body_b.asleep && !body_a.asleep && body_a.moving) wake(body_b);
  }
  // Sphere pairs. Only spheres that reach the other body's box are paired (a grain's 20–60
  // spheres make 400–3600 pairs, of which a touching neighbour needs a few dozen). Pairs come
  // out sorted by key: the body pairs are sorted and the loops run over s_a, then s_b.
  std::vector<Candidate> found;
  std::vector<int> near_a, near_b;
  const auto spheres_near = [&](int body, const Box& other, double reach, std::vector<int>& near) {
    near.clear();
    for (int s = 0; s < bodies[body].sphere_count(); ++s) {
      const Vec3& c = centre(body, s);
      if ((c - c.cwiseMax(other.lower).cwiseMin(other.upper)).norm() - bodies[body].radii[s] < reach) near.push_back(s);
    }
  };
  for (const auto& [a, b] : pairs) {
    if (bodies[a].asleep && bodies[b].asleep) continue;  // sleeping bodies do not touch each other
    const double reach = pad[a] + pad[b];
    spheres_near(a, tight[b], reach, near_a);
    if (near_a.empty()) continue;
    spheres_near(b, tight[a], reach, near_b);
    for (const int sa : near_a)
      for (const int sb : near_b) {
        const double gap = (centre(a, sa) - centre(b, sb)).norm() - bodies[a].radii[sa] - bodies[b].radii[sb];
        if (gap < reach) found.push_back({{a, b, sa, sb}});
      }
  }
  std::vector<Candidate> against_colliders;
  for (size_t c = 0; c < model_.colliders.size(); ++c) {
    const Collider& collider = model_.colliders[c];
    const ColliderKeyframe start = collider_pose(collider, time), end = collider_pose(collider, time + span);
    const bool moving = start.translation != end.translation || start.rotation.coeffs() != end.rotation.coeffs();
    for (size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].asleep && !moving) continue;  // a sleeping body rests on a collider at rest
      for (int s = 0; s < bodies[b].sphere_count(); ++s) {
        const Vec3 local = to_local(start, centre(b, s));
        const double reach = pad[b] + (to_world(end, local) - centre(b, s)).norm();
        if (local_signed_distance(collider, local).distance - bodies[b].radii[s] < reach) {
          against_colliders.push_back({{static_cast<int>(b), collider_key(static_cast<int>(c)), s, 0}});
          wake(model_.bodies[b]);  // a moving collider reaches it
        }
      }
    }
  }
  const auto by_key = [](const Candidate& x, const Candidate& y) { return x.key < y.key; };
  std::sort(against_colliders.begin(), against_colliders.end(), by_key);
  std::vector<Candidate> all(found.size() + against_colliders.size());
  std::merge(found.begin(), found.end(), against_colliders.begin(), against_colliders.end(), all.begin(), by_key);
  found = std::move(all);
  // A pair that stays a candidate keeps its friction state and anchors.
  auto old = candidates_.begin();
  for (Candidate& candidate : found) {
    while (old != candidates_.end() && old->key < candidate.key) ++old;
    if (old != candidates_.end() && old->key == candidate.key) candidate = *old;
    candidate.interval_normal = 0.0;
    candidate.interval_friction.setZero();
  }
  candidates_ = std::move(found);
  statistics_.candidates = static_cast<int>(candidates_.size());
}

void ContactSolver::begin_substep(double time, double h, const Positions& x_previous) {
  h_ = h;
  std::vector<CohesionBonds::Touch> touches;  // filled only when cohesion is on
  pose_start_.clear();
  pose_end_.clear();
  for (const Collider& collider : model_.colliders) {
    pose_start_.push_back(collider_pose(collider, time));
    pose_end_.push_back(collider_pose(collider, time + h));
  }
  // Every sphere centre now (after prediction) and at the substep's start, once.
  centre_now_.resize(sphere_offset_.back());
  centre_start_.resize(sphere_offset_.back());
  for (size_t b = 0; b < model_.bodies.size(); ++b) {
    const Body& body = model_.bodies[b];
    for (int s = 0; s < body.sphere_count(); ++s) {
      const int k = sphere_offset_[b] + s;
      centre_now_[k] = sphere_centre(model_, body, s);
      centre_start_[k] = previous_point(model_, body, s, centre_now_[k], x_previous);
    }
  }
  const double margin = model_.contact.margin;
  contacts_.clear();
  for (size_t c = 0; c < candidates_.size(); ++c) {
    const auto [a, b, sa, sb] = candidates_[c].key;
    const Body& body_a = model_.bodies[a];
    const Vec3& ca = centre_now_[sphere_offset_[a] + sa];
    const Vec3& ca_start = centre_start_[sphere_offset_[a] + sa];
    const double ra = body_a.radii[sa];
    Contact contact{static_cast<int>(c), Vec3::UnitZ(), Vec3::Zero()};
    if (is_collider(b)) {
      const int k = collider_index(b);
      const Collider& collider = model_.colliders[k];
      const Vec3 local = to_local(pose_start_[k], ca_start);
      const SignedDistance sd = local_signed_distance(collider, local);
      const double moved = (ca - ca_start).norm() + (to_world(pose_end_[k], local) - ca_start).norm();
      if (sd.distance - ra >= moved + margin) {
        candidates_[c].anchored = false;
        continue;
      }
      contact.normal = sd.normal;
      contact.collider_point = local - sd.distance * sd.normal;
    } else {
      const Body& body_b = model_.bodies[b];
      const Vec3& cb = centre_now_[sphere_offset_[b] + sb];
      const Vec3& cb_start = centre_start_[sphere_offset_[b] + sb];
      const Vec3 d = ca_start - cb_start;
      const double distance = d.norm();
      const double gap = distance - ra - body_b.radii[sb];
      if (gap >= (ca - ca_start).norm() + (cb - cb_start).norm() + margin) {
        candidates_[c].anchored = false;
        continue;
      }
      if (distance > 0.0) contact.normal = d / distance;
      if (bonds_ && gap <= model_.contact.bond_distance)
        touches.push_back({candidates_[c].key, ca_start - ra * contact.normal, cb_start + body_b.radii[sb] * contact.normal});
    }
    contacts_.push_back(contact);
  }
  statistics_.contacts = static_cast<int>(contacts_.size());
  if (bonds_) bonds_->begin_substep(model_, touches, x_previous);
}

void ContactSolver::project(const Positions& x_previous) {
  // Bonds after the normals: projected first, they left deeper penetrations in a sticky pile
  // (1.6 mm against 1.1 mm, 800 grains) and kept it moving (6e-6 J against 2e-7 J).
  for (Contact& contact : contacts_) project_normal(contact);
  if (bonds_) bonds_->project(model_, h_);
  if (!has_friction_) return;  // frictionless scenes pay nothing for it
  for (Contact& contact : contacts_) project_friction(contact, x_previous);
}

ContactSolver::ContactPoints ContactSolver::locate(const Contact& contact) const {
  const auto [a, b, sa, sb] = candidates_[contact.candidate].key;
  ContactPoints p;
  p.a = &model_.bodies[a];
  const Vec3 ca = sphere_centre(model_, *p.a, sa);
  if (is_collider(b)) {
    const ColliderKeyframe& end = pose_end_[collider_index(b)];
    p.n = end.rotation * contact.normal;
    p.pb = to_world(end, contact.collider_point);
    p.pb_start = to_world(pose_start_[collider_index(b)], contact.collider_point);
  } else {
    p.b = &model_.bodies[b];
    p.n = contact.normal;
    p.pb = sphere_centre(model_, *p.b, sb) + p.b->radii[sb] * p.n;
  }
  p.pa = ca - p.a->radii[sa] * p.n;
  return p;
}

double ContactSolver::inverse_mass(const Contact& contact, const ContactPoints& p, const Vec3& direction) const {
  const auto [a, b, sa, sb] = candidates_[contact.candidate].key;
  return inverse_mass_at(model_, *p.a, sa, p.pa, direction) +
         (p.b ? inverse_mass_at(model_, *p.b, sb, p.pb, direction) : 0.0);
}

void ContactSolver::push(const Contact& contact, const ContactPoints& p, const Vec3& impulse) {
  const auto [a, b, sa, sb] = candidates_[contact.candidate].key;
  apply_impulse_at(model_, *p.a, sa, p.pa, impulse);
  if (p.b) apply_impulse_at(model_, *p.b, sb, p.pb, -impulse);
}

Vec3 ContactSolver::tangential_slip(const Contact& contact, const ContactPoints& p, const Positions& x_previous) const {
  // Relative displacement of the two contact points over the substep, tangential part.
  const auto [a, b, sa, sb] = candidates_[contact.candidate].key;
  const Vec3 da = p.pa - previous_point(model_, *p.a, sa, p.pa, x_previous);
  const Vec3 db = p.b ? Vec3(p.pb - previous_point(model_, *p.b, sb, p.pb, x_previous)) : Vec3(p.pb - p.pb_start);
  const Vec3 d = da - db;
  return d - p.n.dot(d) * p.n;
}

Vec3 ContactSolver::anchored_slip(Candidate& candidate, const ContactPoints& p, const Positions& x_previous) const {
  // Anchors, set once: a's material point now at p_a, and b's material point where p_a was at
  // the substep's start. Their tangential separation is the slip since sticking began.
  const auto [a, b, sa, sb] = candidate.key;
  if (!candidate.anchored) {
    const Vec3 start = previous_point(model_, *p.a, sa, p.pa, x_previous);
    candidate.anchor_a = material_coordinates(model_, *p.a, sa, p.pa);
    candidate.anchor_b = p.b ? material_coordinates(model_, *p.b, sb, start, &x_previous)
                             : to_local(pose_start_[collider_index(b)], start);
    candidate.anchored = true;
  }
  const Vec3 on_b = p.b ? material_point(model_, *p.b, sb, candidate.anchor_b)
                        : to_world(pose_end_[collider_index(b)], candidate.anchor_b);
  const Vec3 d = material_point(model_, *p.a, sa, candidate.anchor_a) - on_b;
  return d - p.n.dot(d) * p.n;
}

void ContactSolver::project_normal(Contact& contact) {
  // C = n·(c_a − c_b) − (r_a + r_b) = n·(p_a − p_b) ≥ 0, α = 0 (MMCJK20 eq. 2–5).
  const ContactPoints p = locate(contact);
  const double C = p.n.dot(p.pa - p.pb);
  if (C >= 0.0) return;
  const double w = inverse_mass(contact, p, p.n);
  if (!(w > 0.0)) return;
  const double delta = -C / w;
  push(contact, p, delta * p.n);
  contact.lambda_normal += delta;
}

void ContactSolver::project_friction(Contact& contact, const Positions& x_previous) {
  // Sticking: cancel the slip since the anchors were set, in full (end_substep checks
  // Coulomb's cone over the pair). Sliding: cancel the slip of this substep with impulses
  // that sum to at most μ_k λ_n.
  Candidate& candidate = candidates_[contact.candidate];
  const int b = candidate.key[1];
  contact.capped = false;
  if (contact.lambda_normal == 0.0) return;  // not touching: no friction
  const ContactPoints p = locate(contact);
  const Vec3 tangential =
      candidate.sliding ? tangential_slip(contact, p, x_previous) : anchored_slip(candidate, p, x_previous);
  const double slip = tangential.norm();
  if (!(slip > 0.0)) return;
  const Vec3 t = tangential / slip;
  const double w = inverse_mass(contact, p, t);
  if (!(w > 0.0)) return;
  const double needed = slip / w;
  double delta = needed;
  if (candidate.sliding) {
    const double mu_k =
        is_collider(b) ? model_.colliders[collider_index(b)].dynamic_friction : model_.contact.dynamic_friction;
    delta = std::min(needed, std::max(mu_k * contact.lambda_normal - contact.lambda_tangent, 0.0));
    contact.capped = needed > delta;
  }
  if (!(delta > 0.0)) return;
  push(contact, p, -delta * t);
  contact.lambda_tangent += delta;
  contact.friction -= delta * t;
}

void ContactSolver::solve_velocities() {
  // MMCJK20 §3.6 with restitution 0: every contact that pushed in this substep leaves its two
  // points with no relative normal velocity. The position solve's corrections, applied at
  // points below the centre of mass, otherwise leave a resting grain rocking.
  for (const Contact& contact : contacts_) {
    if (contact.lambda_normal == 0.0) continue;
    const auto [a, b, sa, sb] = candidates_[contact.candidate].key;
    const ContactPoints p = locate(contact);
    const Vec3 vb = p.b ? velocity_at(model_, *p.b, sb, p.pb) : Vec3((p.pb - p.pb_start) / h_);
    const double vn = p.n.dot(velocity_at(model_, *p.a, sa, p.pa) - vb);
    const double w = inverse_mass(contact, p, p.n);
    if (vn == 0.0 || !(w > 0.0)) continue;
    const Vec3 impulse = (-vn / w) * p.n;
    apply_velocity_impulse_at(model_, *p.a, sa, p.pa, impulse);
    if (p.b) apply_velocity_impulse_at(model_, *p.b, sb, p.pb, -impulse);
  }
}

void ContactSolver::end_substep(bool end_of_interval) {
  // Coulomb's law for a body pair (or a body and a collider) over all its contacts. A sticking
  // pair, whose friction cancelled its slip in full, starts to slide when the net friction
  // impulse over the broad-phase interval |Σ f_t| exceeded μ_s Σλ_n; summing over substeps keeps
  // the brief excess of a landing (Gauss–Seidel lifts a rigid grain a little too far, and the
  // next substep has less normal impulse) from setting a resting grain sliding. A sliding pair
  // sticks again once one touching contact stopped its slip within μ_k λ_n. Judging the
  // pair, not each contact, keeps the contact that Gauss–Seidel visits first, which sees the
  // whole slip, from deciding for all.
  double deepest = 0.0;
  for (size_t first = 0; first < contacts_.size();) {
    const auto& key = candidates_[contacts_[first].candidate].key;
    const bool sliding = candidates_[contacts_[first].candidate].sliding;
    const double mu_s = is_collider(key[1]) ? model_.colliders[collider_index(key[1])].static_friction
                                            : model_.contact.static_friction;
    size_t last = first;
    bool touching = false, stuck = false;
    double normal = 0.0;
    Vec3 friction = Vec3::Zero();
    for (; last < contacts_.size(); ++last) {
      const Contact& contact = contacts_[last];
      Candidate& candidate = candidates_[contact.candidate];
      if (candidate.key[0] != key[0] || candidate.key[1] != key[1]) break;
      const ContactPoints p = locate(contact);
      deepest = std::max(deepest, -p.n.dot(p.pa - p.pb));
      candidate.interval_normal += contact.lambda_normal;
      candidate.interval_friction += contact.friction;
      normal += candidate.interval_normal;
      friction += candidate.interval_friction;
      if (contact.lambda_normal == 0.0) continue;
      touching = true;
      stuck = stuck || !contact.capped;
    }
    const bool slides =
        has_friction_ && touching && (sliding ? !stuck : end_of_interval && friction.norm() > mu_s * normal);
    for (size_t c = first; c < last; ++c) {
      Candidate& candidate = candidates_[contacts_[c].candidate];
      candidate.sliding = slides;
      candidate.anchored = candidate.anchored && !slides && contacts_[c].lambda_normal > 0.0;
    }
    first = last;
  }
  statistics_.max_penetration = deepest;
  if (bonds_) update_bonds();
}

void ContactSolver::update_bonds() {
  bonds_->end_substep(h_);
  statistics_.bonds = bonds_->count();
  statistics_.bonds_broken = bonds_->broken();
}

}  // namespace rice::xpbd
