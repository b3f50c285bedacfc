// Broad phase, speculative contacts and their projection with friction; see contact_solver.hpp.
#include "xpbd/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

#include "xpbd/broad_phase.hpp"
#include "xpbd/sleeping.hpp"
#include "xpbd/state_archive.hpp"

namespace rice::xpbd {

// ---- One side of a contact: body.hpp's operations, a soft side's on its anchor ----

ContactSolver::Side ContactSolver::side(int body, int s) const {
  const Body& b = model_.bodies[body];
  return {&b, b.kind == BodyKind::kSoft ? &b.anchors[s] : nullptr, radius(body, s), s, b.asleep};
}

Vec3 ContactSolver::Side::centre(const Model& model) const {
  return anchor ? anchor->at(model.particles.x) : sphere_centre(model, *body, s);
}

Vec3 ContactSolver::Side::previous_point(const Model& model, const Vec3& point, const Positions& x_previous) const {
  return anchor ? Vec3(point - anchor->displacement(model.particles.x, x_previous))
                : xpbd::previous_point(model, *body, s, point, x_previous);
}

double ContactSolver::Side::inverse_mass(const Model& model, const Vec3& point, const Vec3& n) const {
  if (asleep) return 0.0;
  return anchor ? anchor->inverse_mass(model.particles.w) : inverse_mass_at(model, *body, s, point, n);
}

void ContactSolver::Side::apply_impulse(Model& model, const Vec3& point, const Vec3& p) const {
  if (asleep) return;
  if (anchor) anchor->apply(model.particles.x, model.particles.w, p);
  else apply_impulse_at(model, *body, s, point, p);
}

Vec3 ContactSolver::Side::velocity(const Model& model, const Vec3& point) const {
  return anchor ? anchor->at(model.particles.v) : velocity_at(model, *body, s, point);
}

void ContactSolver::Side::apply_velocity_impulse(Model& model, const Vec3& point, const Vec3& p) const {
  if (asleep) return;
  if (anchor) anchor->apply(model.particles.v, model.particles.w, p);
  else apply_velocity_impulse_at(model, *body, s, point, p);
}

Vec3 ContactSolver::Side::material_point(const Model& model, const Vec3& c, const Vec3& coordinates) const {
  return anchor ? Vec3(c + coordinates) : xpbd::material_point(model, *body, s, coordinates);
}

Vec3 ContactSolver::Side::coordinates_now(const Model& model, const Vec3& c, const Vec3& point) const {
  return anchor ? Vec3(point - c) : material_coordinates(model, *body, s, point);
}

Vec3 ContactSolver::Side::coordinates_then(const Model& model, const Vec3& point, const Positions& x_previous) const {
  return anchor ? Vec3(point - anchor->at(x_previous)) : material_coordinates(model, *body, s, point, &x_previous);
}

// ---- The contact solver ----

ContactSolver::ContactSolver(Model& model, bool parallel) : model_(model), parallel_(parallel) {
  const ContactSettings& s = model.contact;
  if (!(s.static_friction >= 0.0 && s.dynamic_friction >= 0.0 && s.dynamic_friction <= s.static_friction))
    throw std::invalid_argument("contact: need 0 <= dynamic friction <= static friction between grains");
  if (!(s.margin >= 0.0 && std::isfinite(s.margin))) throw std::invalid_argument("contact: margin must be >= 0");
  if (!(s.bond_compliance >= 0.0 && std::isfinite(s.bond_compliance)))
    throw std::invalid_argument("contact: bond compliance must be >= 0");
  if (!(s.bond_distance >= 0.0 && std::isfinite(s.bond_distance)))
    throw std::invalid_argument("contact: bond distance must be >= 0");
  if (!(s.particle_stiffness > 0.0 && std::isfinite(s.particle_stiffness)))
    throw std::invalid_argument("contact: particle stiffness must be > 0");
  if (s.cohesion) bonds_.emplace();
  sphere_offset_.assign(1, 0);
  for (const Body& body : model.bodies) sphere_offset_.push_back(sphere_offset_.back() + body.sphere_count());
  centre_now_.resize(sphere_offset_.back());
  centre_start_.resize(sphere_offset_.back());
  radius_.resize(sphere_offset_.back());
  start_box_.assign(model.bodies.size(), {Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)});  // empty
  motion_.assign(model.bodies.size(), 0.0);
  centres_at_rest_.assign(model.bodies.size(), 0);
  body_of_particle_ = soft_body_of_particle(model);
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
  // Bodies whose centres were last computed asleep, before they are computed again: a grain
  // parked asleep and moved into the scene (an emitter's release) has no motion since the last
  // broad phase to go by, only its jump.
  const std::vector<char> asleep_then = centres_at_rest_;
  for_each_body(static_cast<int>(bodies.size()), [&](int b) { update_centres(b, nullptr, true); });
  radii_time_ = time;
  for (size_t b = 0; b < bodies.size(); ++b)
    pad[b] = motion_bound(static_cast<int>(b), time, span, asleep_then[b] != 0) + margin;
  centre_at_broad_phase_ = centre_now_;
  broad_phase_time_ = time;
  sphere_pairs_.clear();
  // Colliders first: one in motion wakes what it reaches and can push it as far as it moves,
  // which the body's own motion bound, from its speed, does not know; its pad grows by that
  // much, so that its neighbours, asleep or awake, are candidates too. (Looked for after, a
  // grain woken by a pressing box met its sleeping neighbour only at the next broad phase,
  // 0.11 mm inside it.)
  std::vector<BodyPair> found;
  const std::vector<double> own_pad = pad;
  add_collider_candidates(time, span, pad, found, true);
  std::vector<Box> boxes(bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b)
    boxes[b] = {start_box_[b].lower - Vec3::Constant(pad[b]), start_box_[b].upper + Vec3::Constant(pad[b])};
  const std::vector<std::pair<int, int>> pairs = overlapping_pairs(boxes);
  // A body that moved in the last step, or that a collider pushes, wakes the sleeping bodies
  // its box reaches.
  const auto pushing = [&](int b) { return bodies[b].moving || pad[b] > own_pad[b]; };
  for (const auto& [a, b] : pairs) {
    if (bodies[a].asleep && !bodies[b].asleep && pushing(b)) wake(model_.bodies[a]);
    if (bodies[b].asleep && !bodies[a].asleep && pushing(a)) wake(model_.bodies[b]);
  }
  const std::vector<BodyPair> between_bodies = body_candidates(pairs, pad);
  found.insert(found.end(), between_bodies.begin(), between_bodies.end());
  // Colliders at rest last, so that they meet the bodies just woken too.
  add_collider_candidates(time, span, pad, found, false);
  // In key order: by body a, then b (colliders, with negative keys, first).
  std::sort(found.begin(), found.end(), [](const BodyPair& x, const BodyPair& y) {
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
  body_pairs_ = std::move(found);
  keep_states_in_reach();
  statistics_.candidates = 0;
  active_bodies_.clear();
  for (const BodyPair& p : body_pairs_) {
    statistics_.candidates += p.last - p.first;
    active_bodies_.push_back(p.a);
    if (!is_collider(p.b)) active_bodies_.push_back(p.b);
  }
  std::sort(active_bodies_.begin(), active_bodies_.end());
  active_bodies_.erase(std::unique(active_bodies_.begin(), active_bodies_.end()), active_bodies_.end());
}

std::vector<ContactSolver::BodyPair> ContactSolver::body_candidates(const std::vector<std::pair<int, int>>& pairs,
                                                                    const std::vector<double>& pad) {
  // Candidate sphere pairs of each body pair: spheres that reach the other body's box, paired
  // when their gap is within reach (a grain's 20–60 spheres make 400–3600 pairs, of which a
  // touching neighbour needs a few dozen). The body pairs in chunks of a fixed size, in
  // parallel, each into its own lists, joined in order: the same lists on any thread count
  // (it was 28% of a 10,000-grain rigid run, on one core).
  constexpr int kChunk = 256, kWave = 16;
  struct Found {
    std::vector<std::array<int, 2>> spheres;
    std::vector<BodyPair> bodies;  ///< first and last index into `spheres`
  };
  const auto& bodies = model_.bodies;
  const auto find_in = [&](int chunk, Found& out) {
    std::vector<int> near_a, near_b;
    const size_t end = std::min(pairs.size(), static_cast<size_t>(chunk + 1) * kChunk);
    for (size_t k = static_cast<size_t>(chunk) * kChunk; k < end; ++k) {
      const int a = pairs[k].first, b = pairs[k].second;
      if (bodies[a].asleep && bodies[b].asleep) continue;  // sleeping bodies do not touch each other
      const double reach = pad[a] + pad[b];
      spheres_near(a, centre_now_, start_box_[b], reach, near_a);
      if (near_a.empty()) continue;
      spheres_near(b, centre_now_, start_box_[a], reach, near_b);
      // Listed up to as many pairs as a substep's search over both bodies' spheres checks;
      // past that, searched in each substep instead.
      const size_t first = out.spheres.size(), most = bodies[a].sphere_count() + bodies[b].sphere_count();
      const auto list = [&] {
        for (const int sa : near_a)
          for (const int sb : near_b) {
            const Vec3 d = centre_now_[sphere_offset_[a] + sa] - centre_now_[sphere_offset_[b] + sb];
            if (d.norm() - radius(a, sa) - radius(b, sb) >= reach) continue;
            if (out.spheres.size() - first == most) return false;
            out.spheres.push_back({sa, sb});
          }
        return true;
      };
      if (!list()) {
        out.spheres.resize(first);
        out.bodies.push_back({a, b, kEachSubstep, kEachSubstep});
      } else if (out.spheres.size() > first) {
        out.bodies.push_back({a, b, static_cast<int>(first), static_cast<int>(out.spheres.size())});
      }
    }
  };
  // A wave of chunks at a time: the lists a wave holds before they are joined stay small (all
  // chunks at once held a second copy of the sphere pairs: 475 -> 655 MiB at 3000 grains).
  std::vector<Found> wave(kWave);
  std::vector<BodyPair> found;
  const int chunks = static_cast<int>((pairs.size() + kChunk - 1) / kChunk);
  for (int first = 0; first < chunks; first += kWave) {
    const int count = std::min(kWave, chunks - first);
    const auto find_chunk = [&](int c) {
      wave[c].spheres.clear();
      wave[c].bodies.clear();
      find_in(first + c, wave[c]);
    };
    if (parallel_)
      tbb::parallel_for(0, count, find_chunk);
    else
      for (int c = 0; c < count; ++c) find_chunk(c);
    for (int c = 0; c < count; ++c) {
      const int offset = static_cast<int>(sphere_pairs_.size());
      for (BodyPair p : wave[c].bodies)
        found.push_back(p.each_substep() ? p : BodyPair{p.a, p.b, p.first + offset, p.last + offset});
      sphere_pairs_.insert(sphere_pairs_.end(), wave[c].spheres.begin(), wave[c].spheres.end());
    }
  }
  return found;
}

void ContactSolver::spheres_near(int body, const std::vector<Vec3>& centres, const Box& box, double reach,
                                 std::vector<int>& near) const {
  near.clear();
  for (int s = 0; s < model_.bodies[body].sphere_count(); ++s) {
    const Vec3& c = centres[sphere_offset_[body] + s];
    if ((c - c.cwiseMax(box.lower).cwiseMin(box.upper)).norm() - radius(body, s) < reach) near.push_back(s);
  }
}

void ContactSolver::add_collider_candidates(double time, double span, std::vector<double>& pad,
                                            std::vector<BodyPair>& found, bool moving_ones) {
  const auto& bodies = model_.bodies;
  for (size_t c = 0; c < model_.colliders.size(); ++c) {
    const Collider& collider = model_.colliders[c];
    if (!collider_present(collider, time)) continue;
    const ColliderKeyframe start = collider_pose(collider, time), end = collider_pose(collider, time + span);
    // A yielding collider may move in any substep, as far as yield_reach.
    const double reach = yields(collider) ? yield_reach(collider, time, span) : 0.0;
    // A collider that goes in this interval wakes what rests on it, as one that moves.
    const bool moving = reach > 0.0 || !same_pose(start, end) || !collider_present(collider, time + span);
    if (moving != moving_ones) continue;
    for (size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].asleep && !moving) continue;  // a sleeping body rests on a collider at rest
      if (!moving && out_of_reach(collider, start, start_box_[b], pad[b])) continue;
      const int first = static_cast<int>(sphere_pairs_.size());
      double pushed = 0.0;  // how far the collider moves where it reaches the body
      for (int s = 0; s < bodies[b].sphere_count(); ++s) {
        const Vec3& centre = centre_now_[sphere_offset_[b] + s];
        const Vec3 local = to_local(start, centre);
        const double moved = (to_world(end, local) - centre).norm() + reach;
        if (posed_signed_distance(collider, start, local).distance - radius(static_cast<int>(b), s) < pad[b] + moved) {
          sphere_pairs_.push_back({s, 0});
          pushed = std::max(pushed, moved);
        }
      }
      const int last = static_cast<int>(sphere_pairs_.size());
      if (last == first) continue;
      found.push_back({static_cast<int>(b), collider_key(static_cast<int>(c)), first, last});
      if (bodies[b].asleep) wake(model_.bodies[b]);  // a moving collider reaches it
      if (moving) pad[b] += pushed;  // (at rest, `moved` is round-off)
    }
  }
}

void ContactSolver::keep_states_in_reach() {
  // The contact states of pairs that stay in reach carry over, with their interval sums reset,
  // compacted in place (a new vector each broad phase was grown from nothing).
  size_t kept = 0;
  auto pair = body_pairs_.begin();
  for (ContactState& state : states_) {
    const std::pair<int, int> key(state.key[0], state.key[1]);
    while (pair != body_pairs_.end() && std::pair(pair->a, pair->b) < key) ++pair;
    if (pair == body_pairs_.end() || std::pair(pair->a, pair->b) != key) continue;
    state.interval_normal = 0.0;
    state.interval_friction.setZero();
    states_[kept++] = state;
  }
  states_.resize(kept);
}

template <class Function>
void ContactSolver::for_each_body(int count, const Function& function) const {
  if (!parallel_) {
    for (int k = 0; k < count; ++k) function(k);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, count, 64), [&](const tbb::blocked_range<int>& range) {
    for (int k = range.begin(); k < range.end(); ++k) function(k);
  });
}

double ContactSolver::motion_bound(int b, double time, double span, bool woken) const {
  const Body& body = model_.bodies[b];
  if (body.asleep) return 0.0;
  double speed = 0.0, growth = 0.0;
  if (body.kind == BodyKind::kRigid) {
    const RigidBody& rigid = model_.rigid_bodies[body.rigid_body];
    if (rigid.inverse_mass == 0.0) return 0.0;
    speed = rigid.v.norm() + rigid.omega.norm() * reach(body);
  } else if (time > broad_phase_time_ && !woken) {
    // The fastest sphere centre's mean speed since the last broad phase: a landed grain that
    // rings has particles at ~1 m/s moving back and forth by some 50 µm, and their speed
    // would pad its box by centimetres. A sphere may also regrow to its rest radius. (Not for
    // a body asleep then: a grain released from its parking place metres away read as moving
    // at hundreds of m/s, its box padded by metres paired it with every grain in the rice
    // cooker's pot, and each round of the fill took 5 GB and doubled its frame's time.)
    for (int s = 0; s < body.sphere_count(); ++s) {
      const int k = sphere_offset_[b] + s;
      speed = std::max(speed, (centre_now_[k] - centre_at_broad_phase_[k]).norm() / (time - broad_phase_time_));
      growth = std::max(growth, body.radii[s] - radius_[k]);
    }
  } else {
    for (int i = body.first_particle; i < body.first_particle + body.particle_count; ++i)
      speed = std::max(speed, model_.particles.v.row(i).norm());
  }
  return 1.5 * speed * span + 0.5 * model_.gravity.norm() * span * span + growth;
}

void ContactSolver::update_centres(int b, const Positions* x_previous, bool radii) {
  const Body& body = model_.bodies[b];
  if (body.asleep && centres_at_rest_[b]) return;  // a sleeping body does not move
  Box box{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  double motion = 0.0;
  for (int s = 0; s < body.sphere_count(); ++s) {
    const int k = sphere_offset_[b] + s;
    centre_now_[k] = sphere_centre(model_, body, s);
    if (radii) radius_[k] = sphere_radius(model_, body, s);
    centre_start_[k] = x_previous && !body.asleep ? previous_point(model_, body, s, centre_now_[k], *x_previous)
                                                   : centre_now_[k];
    box.lower = box.lower.cwiseMin(centre_start_[k] - Vec3::Constant(radius_[k]));
    box.upper = box.upper.cwiseMax(centre_start_[k] + Vec3::Constant(radius_[k]));
    motion = std::max(motion, (centre_now_[k] - centre_start_[k]).norm());
  }
  start_box_[b] = box;
  motion_[b] = motion;
  centres_at_rest_[b] = body.asleep;
}

bool ContactSolver::may_touch(const BodyPair& pair) const {
  const double margin = model_.contact.margin;
  const Box& box_a = start_box_[pair.a];
  if (!is_collider(pair.b)) {
    // The distance between two spheres is at least that between boxes holding them.
    const Box& box_b = start_box_[pair.b];
    const Vec3 separation = (box_b.lower - box_a.upper).cwiseMax(box_a.lower - box_b.upper).cwiseMax(0.0);
    return separation.norm() < motion_[pair.a] + motion_[pair.b] + margin;
  }
  const int k = collider_index(pair.b);
  if (!present_[k]) return false;
  if (!same_pose(pose_start_[k], pose_end_[k])) return true;
  return !out_of_reach(model_.colliders[k], pose_start_[k], box_a, motion_[pair.a] + margin);
}

bool ContactSolver::out_of_reach(const Collider& collider, const ColliderKeyframe& pose, const Box& box,
                                 double reach) {
  // A sphere in the box is at least the distance at the box's centre less L times the half
  // diagonal from the collider, L bounding the distance's gradient (√3 for a trilinear grid,
  // whose gradient has components of at most 1; 1 for the analytic shapes).
  const double lipschitz = collider.shape == ColliderShape::kDistanceGrid ? std::sqrt(3.0) : 1.0;
  const Vec3 centre = 0.5 * (box.lower + box.upper);
  const double half_diagonal = 0.5 * (box.upper - box.lower).norm();
  return posed_signed_distance(collider, pose, to_local(pose, centre)).distance - lipschitz * half_diagonal >= reach;
}

void ContactSolver::begin_substep(double time, double h, const Positions& x_previous) {
  h_ = h;
  std::vector<CohesionBonds::Touch> touches;  // filled only when cohesion is on
  pose_start_.clear();
  pose_end_.clear();
  present_.clear();
  for (Collider& collider : model_.colliders) {
    if (yields(collider)) collider.yield = next_yield(collider, time, h);
    pose_start_.push_back(collider_pose(collider, time));
    pose_end_.push_back(collider_pose(collider, time + h));
    present_.push_back(collider_present(collider, time));
  }
  // The sphere centres of every body with candidates, now (after prediction) and at the
  // substep's start, once; their radii once a radius_interval.
  const bool radii = time >= radii_time_ + model_.contact.radius_interval * (1.0 - 1e-9);
  if (radii) radii_time_ = time;
  for_each_body(static_cast<int>(active_bodies_.size()),
                [&](int k) { update_centres(active_bodies_[k], &x_previous, radii); });
  // Contacts come out in key order, so the states of the last substep are merged in one pass;
  // a state whose spheres do not touch in this substep loses its anchors. The two buffers
  // swap, keeping their memory: a buffer moved from and grown again each substep took a
  // third of a 10,000-grain clump's time in page faults.
  std::swap(states_, previous_states_);
  std::vector<ContactState>& previous = previous_states_;
  states_.clear();
  auto old = previous.begin();
  // A state whose spheres are not in contact now loses its anchors and held forces; one left
  // with nothing a new state would not have (not sliding, no impulse in this interval) is
  // dropped, so that the states of a pile are about its contacts, not every sphere pair that
  // touched since its body pair came in reach (41 a grain against 3.2 contacts in a
  // 3000-grain clump, all copied every substep). The runs are the same to the bit. (Dropping
  // the sliding ones too changed them, and left the pressed bunny of the hard cases with
  // two tets inverted.)
  const auto carry_untouched = [&](ContactState& state) {
    state.anchored = state.flown = false;
    state.particle_force = 0.0;
    state.friction_force.setZero();
    if (state.sliding || state.interval_normal != 0.0 || !state.interval_friction.isZero(0.0))
      states_.push_back(state);
  };
  const auto state_of = [&](const std::array<int, 4>& key) {
    for (; old != previous.end() && old->key < key; ++old) carry_untouched(*old);
    if (old != previous.end() && old->key == key) {
      states_.push_back(*old++);
    } else {
      states_.push_back({key});
    }
    return static_cast<int>(states_.size()) - 1;
  };
  contacts_.clear();
  for (const BodyPair& pair : body_pairs_)
    if (may_touch(pair)) add_contacts(pair, state_of, touches);
  for (; old != previous.end(); ++old) carry_untouched(*old);
  statistics_.contacts = static_cast<int>(contacts_.size());
  statistics_.states = static_cast<int>(states_.size());
  if (bonds_) bonds_->begin_substep(model_, touches, x_previous);
  if (!particle_steps_) return;
  particle_contacts_.clear();
  for (Contact& contact : contacts_) {
    const auto [a, b, sa, sb] = states_[contact.state].key;
    if (model_.bodies[a].kind != BodyKind::kSoft || (!is_collider(b) && model_.bodies[b].kind != BodyKind::kSoft))
      continue;
    contact.particle_contact = static_cast<int>(particle_contacts_.contacts().size());
    particle_contacts_.add(make_particle_contact(contact, x_previous));
  }
  if (bonds_) bonds_->hold_in_particle_steps(model_, particle_contacts_);
  particle_contacts_.index(model_.particles.size(), body_of_particle_, static_cast<int>(model_.bodies.size()));
  particle_contacts_.set_friction_bounds(model_.particles.x);
}

ParticleContact ContactSolver::make_particle_contact(const Contact& contact, const Positions& x_previous) const {
  const ContactState& state = states_[contact.state];
  const auto [a, b, sa, sb] = state.key;
  ParticleContact c;
  c.force = state.particle_force;
  c.stiffness = model_.contact.particle_stiffness;
  const auto add_sphere = [&](const Body& body, int s, double sign) {
    for (int k = 0; k < 4; ++k) {
      c.point.particles[c.point.size] = body.anchors[s].particles[k];
      c.point.weights[c.point.size++] = sign * body.anchors[s].weights[k];
    }
  };
  add_sphere(model_.bodies[a], sa, 1.0);
  Vec3 collider_motion = Vec3::Zero();  // of the collider point over the substep
  if (is_collider(b)) {
    const ColliderKeyframe& end = pose_end_[collider_index(b)];
    c.normal = end.rotation * contact.normal;
    const Vec3 q = to_world(end, contact.collider_point);
    c.offset = c.normal.dot(q) + radius(a, sa);
    collider_motion = q - to_world(pose_start_[collider_index(b)], contact.collider_point);
  } else {
    add_sphere(model_.bodies[b], sb, -1.0);
    c.normal = contact.normal;
    c.offset = radius(a, sa) + radius(b, sb);
  }
  if (has_friction_) {
    c.friction = state.sliding ? dynamic_friction(b) : static_friction(b);
    c.slip_origin = c.point.at(x_previous) + collider_motion;
    // The last substep's friction force, in this substep's tangent plane.
    c.friction_force = state.friction_force - c.normal.dot(state.friction_force) * c.normal;
  }
  return c;
}

void ContactSolver::update_particle_contacts() {
  const Positions& x = model_.particles.x;
  for (Contact& contact : contacts_) {
    if (contact.particle_contact < 0) continue;
    const ParticleContact& c = particle_contacts_.contacts()[contact.particle_contact];
    contact.lambda_normal = c.push(x) * h_ * h_;
    // The friction impulse on a over the substep: f_t h² (a's corners take +a_j f_t).
    if (c.friction_bound > 0.0) contact.friction = c.friction_at(c.point.at(x), c.friction_bound) * (h_ * h_);
  }
  particle_contacts_.set_friction_bounds(x);
}

template <class StateOf>
void ContactSolver::add_contacts(const BodyPair& pair, StateOf& state_of, std::vector<CohesionBonds::Touch>& touches) {
  // A contact for every sphere pair whose gap at the substep's start is smaller than the
  // distance its two sides move in the substep and the margin.
  const double margin = model_.contact.margin;
  const auto now = [&](int body, int s) -> const Vec3& { return centre_now_[sphere_offset_[body] + s]; };
  const auto start = [&](int body, int s) -> const Vec3& { return centre_start_[sphere_offset_[body] + s]; };
  if (is_collider(pair.b)) {
    const int k = collider_index(pair.b);
    const Collider& collider = model_.colliders[k];
    for (int i = pair.first; i < pair.last; ++i) {
      const int sa = sphere_pairs_[i][0];
      const Vec3 local = to_local(pose_start_[k], start(pair.a, sa));
      const SignedDistance sd = posed_signed_distance(collider, pose_start_[k], local);
      const double moved =
          (now(pair.a, sa) - start(pair.a, sa)).norm() + (to_world(pose_end_[k], local) - start(pair.a, sa)).norm();
      if (sd.distance - radius(pair.a, sa) >= moved + margin) continue;
      contacts_.push_back({state_of({pair.a, pair.b, sa, 0}), sd.normal,
                           local - (sd.distance / pose_start_[k].scale) * sd.normal});
      contacts_.back().sides[0] = side(pair.a, sa);
    }
    return;
  }
  const auto add = [&](int sa, int sb) {
    const Vec3 d = start(pair.a, sa) - start(pair.b, sb);
    const double distance = d.norm();
    const double gap = distance - radius(pair.a, sa) - radius(pair.b, sb);
    if (gap >= (now(pair.a, sa) - start(pair.a, sa)).norm() + (now(pair.b, sb) - start(pair.b, sb)).norm() + margin)
      return;
    const Vec3 normal = distance > 0.0 ? Vec3(d / distance) : Vec3::UnitZ();
    const std::array<int, 4> key{pair.a, pair.b, sa, sb};
    contacts_.push_back({state_of(key), normal, Vec3::Zero()});
    contacts_.back().sides = {side(pair.a, sa), side(pair.b, sb)};
    if (bonds_ && gap <= model_.contact.bond_distance)
      touches.push_back(
          {key, start(pair.a, sa) - radius(pair.a, sa) * normal, start(pair.b, sb) + radius(pair.b, sb) * normal});
  };
  if (!pair.each_substep()) {
    for (int i = pair.first; i < pair.last; ++i) add(sphere_pairs_[i][0], sphere_pairs_[i][1]);
    return;
  }
  // The spheres of each body within this substep's reach of the other's box (a box holds its
  // body's spheres, so a pair outside it is farther apart than its gap test allows), in the
  // order a list from the broad phase would have them.
  const double reach = motion_[pair.a] + motion_[pair.b] + margin;
  std::vector<int>& near_a = near_[0];
  std::vector<int>& near_b = near_[1];
  spheres_near(pair.a, centre_start_, start_box_[pair.b], reach, near_a);
  if (near_a.empty()) return;
  spheres_near(pair.b, centre_start_, start_box_[pair.a], reach, near_b);
  for (const int sa : near_a)
    for (const int sb : near_b) add(sa, sb);
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
  const int b = states_[contact.state].key[1];
  ContactPoints p;
  p.a = &contact.sides[0];
  p.ca = p.a->centre(model_);
  if (is_collider(b)) {
    const ColliderKeyframe& end = pose_end_[collider_index(b)];
    p.n = end.rotation * contact.normal;
    p.pb = to_world(end, contact.collider_point);
    p.pb_start = to_world(pose_start_[collider_index(b)], contact.collider_point);
  } else {
    p.b = &contact.sides[1];
    p.n = contact.normal;
    p.cb = p.b->centre(model_);
    p.pb = p.cb + p.b->radius * p.n;
  }
  p.pa = p.ca - p.a->radius * p.n;
  return p;
}

double ContactSolver::inverse_mass(const ContactPoints& p, const Vec3& direction) const {
  return p.a->inverse_mass(model_, p.pa, direction) + (p.b ? p.b->inverse_mass(model_, p.pb, direction) : 0.0);
}

void ContactSolver::push(const ContactPoints& p, const Vec3& impulse) {
  p.a->apply_impulse(model_, p.pa, impulse);
  if (p.b) p.b->apply_impulse(model_, p.pb, -impulse);
}

Vec3 ContactSolver::tangential_slip(const ContactPoints& p, const Positions& x_previous) const {
  // Relative displacement of the two contact points over the substep, tangential part.
  const Vec3 da = p.pa - p.a->previous_point(model_, p.pa, x_previous);
  const Vec3 db = p.b ? Vec3(p.pb - p.b->previous_point(model_, p.pb, x_previous)) : Vec3(p.pb - p.pb_start);
  const Vec3 d = da - db;
  return d - p.n.dot(d) * p.n;
}

Vec3 ContactSolver::anchored_slip(ContactState& state, const ContactPoints& p, const Positions& x_previous) const {
  // Anchors, set once: a's material point now at p_a, and b's material point where p_a was at
  // the substep's start. Their tangential separation is the slip since sticking began.
  const int b = state.key[1];
  if (!state.anchored) {
    const Vec3 start = p.a->previous_point(model_, p.pa, x_previous);
    state.anchor_a = p.a->coordinates_now(model_, p.ca, p.pa);
    state.anchor_b = p.b ? p.b->coordinates_then(model_, start, x_previous)
                         : to_local(pose_start_[collider_index(b)], start);
    state.anchored = true;
  }
  const Vec3 on_b = p.b ? p.b->material_point(model_, p.cb, state.anchor_b)
                        : to_world(pose_end_[collider_index(b)], state.anchor_b);
  const Vec3 d = p.a->material_point(model_, p.ca, state.anchor_a) - on_b;
  return d - p.n.dot(d) * p.n;
}

void ContactSolver::project_normal(Contact& contact) {
  // C = n·(c_a − c_b) − (r_a + r_b) = n·(p_a − p_b) ≥ 0, α = 0 (MMCJK20 eq. 2–5).
  if (contact.particle_contact >= 0) return;  // held in the particles' steps
  const ContactPoints p = locate(contact);
  const double C = p.n.dot(p.pa - p.pb);
  if (C >= 0.0) return;
  const double w = inverse_mass(p, p.n);
  if (!(w > 0.0)) return;
  const double delta = -C / w;
  push(p, delta * p.n);
  contact.lambda_normal += delta;
}

void ContactSolver::project_friction(Contact& contact, const Positions& x_previous) {
  // Sticking: cancel the slip since the anchors were set, in full (end_substep checks
  // Coulomb's cone over the pair). Sliding: cancel the slip of this substep with impulses
  // that sum to at most μ_k λ_n.
  ContactState& state = states_[contact.state];
  const int b = state.key[1];
  contact.capped = false;
  if (contact.particle_contact >= 0) return;  // a term of the particles' steps
  // Not touching: no friction. A sticking contact keeps the anchors it set on touching
  // through the flight, so that the slip it makes off the surface counts when it touches
  // again (end_substep). A sphere chattering at the substep rate, touching every other substep,
  // moved forward only in its flights, and a bonded pair slid off over the plate at 7.7 cm/s
  // without friction. A pair that has not touched sets none: its anchors would lie a gap
  // apart, and as the normal turned the gap read as slip (a shari kept a 0.5 mm overlap and 97
  // of 270 grains awake).
  if (contact.lambda_normal == 0.0) return;
  const ContactPoints p = locate(contact);
  const Vec3 tangential =
      state.sliding ? tangential_slip(p, x_previous) : anchored_slip(state, p, x_previous);
  const double slip = tangential.norm();
  if (!(slip > 0.0)) return;
  const Vec3 t = tangential / slip;
  const double w = inverse_mass(p, t);
  if (!(w > 0.0)) return;
  const double needed = slip / w;
  double delta = needed;
  // Sliding, or back from a flight: friction takes back at most μ_k λ_n (taken back in full,
  // the slip of a flight threw a grain of a pressed pile 3 cm up and broke twice the bonds).
  if (state.sliding || state.flown) {
    const double mu_k = dynamic_friction(b);
    delta = std::min(needed, std::max(mu_k * contact.lambda_normal - contact.lambda_tangent, 0.0));
    contact.capped = needed > delta;
  }
  if (!(delta > 0.0)) return;
  push(p, -delta * t);
  contact.lambda_tangent += delta;
  contact.friction -= delta * t;
}

void ContactSolver::restart_anchors(ContactState& state, const ContactPoints& p) const {
  // The slip friction could not take back has slid: b's anchor moves to where a's is now.
  const Vec3 on_a = p.a->material_point(model_, p.ca, state.anchor_a);
  state.anchor_b =
      p.b ? p.b->coordinates_now(model_, p.cb, on_a) : to_local(pose_end_[collider_index(state.key[1])], on_a);
}

void ContactSolver::solve_velocities() {
  // MMCJK20 §3.6 with restitution 0: every contact that pushed in this substep leaves its two
  // points with no relative normal velocity. The position solve's corrections, applied at
  // points below the centre of mass, otherwise leave a resting grain rocking.
  for (size_t c = 0; c < contacts_.size(); ++c) {
    const Contact& contact = contacts_[c];
    if (contact.lambda_normal == 0.0) continue;
    const ContactPoints& p = located_[c];
    const Vec3 vb = p.b ? p.b->velocity(model_, p.pb) : Vec3((p.pb - p.pb_start) / h_);
    const double vn = p.n.dot(p.a->velocity(model_, p.pa) - vb);
    const double w = inverse_mass(p, p.n);
    if (vn == 0.0 || !(w > 0.0)) continue;
    const Vec3 impulse = (-vn / w) * p.n;
    p.a->apply_velocity_impulse(model_, p.pa, impulse);
    if (p.b) p.b->apply_velocity_impulse(model_, p.pb, -impulse);
  }
}

size_t ContactSolver::end_pair_substep(size_t first, bool end_of_interval, double& deepest) {
  // Coulomb's law for a body pair (or a body and a collider) over all its contacts. A sticking
  // pair, whose friction cancelled its slip in full, starts to slide when the net friction
  // impulse over the broad-phase interval |Σ f_t| exceeded μ_s Σλ_n; summing over substeps keeps
  // the brief excess of a landing (Gauss–Seidel lifts a rigid grain a little too far, and the
  // next substep has less normal impulse) from setting a resting grain sliding. A sliding pair
  // sticks again once one touching contact stopped its slip within μ_k λ_n. Judging the
  // pair, not each contact, keeps the contact that Gauss–Seidel visits first, which sees the
  // whole slip, from deciding for all.
  const auto& key = states_[contacts_[first].state].key;
  const bool sliding = states_[contacts_[first].state].sliding;
  const double mu_s = static_friction(key[1]);
  size_t last = first;
  bool touching = false, stuck = false;
  double normal = 0.0;
  Vec3 friction = Vec3::Zero();
  for (; last < contacts_.size(); ++last) {
    const Contact& contact = contacts_[last];
    ContactState& state = states_[contact.state];
    if (state.key[0] != key[0] || state.key[1] != key[1]) break;
    const ContactPoints& p = located_[last] = locate(contact);
    deepest = std::max(deepest, -p.n.dot(p.pa - p.pb));
    if (is_collider(key[1])) {
      const Vec3 impulse = (contact.lambda_normal * p.n + contact.friction) / h_;  // on the grain
      substep_impulses_[collider_index(key[1])] -= impulse;
    }
    state.interval_normal += contact.lambda_normal;
    state.interval_friction += contact.friction;
    normal += state.interval_normal;
    friction += state.interval_friction;
    if (contact.lambda_normal == 0.0) continue;
    touching = true;
    stuck = stuck || !contact.capped;
  }
  const bool slides =
      has_friction_ && touching && (sliding ? !stuck : end_of_interval && friction.norm() > mu_s * normal);
  // Held in the particles' steps, the pair slides when every one of its touching contacts
  // ended the substep on its cone, and sticks when one lay inside. (Judged contact by contact,
  // a grain set on a plane tilted to 0.9 μ_s saw three of its ten contacts reach the cone,
  // slide at μ_k, hand their load to the others, and the whole grain slid away.)
  bool held_touching = false, all_on_cone = true;
  for (size_t c = first; c < last; ++c) {
    if (contacts_[c].particle_contact < 0) continue;
    const ParticleContact& held = particle_contacts_.contacts()[contacts_[c].particle_contact];
    if (held.force == 0.0) continue;
    held_touching = true;
    all_on_cone = all_on_cone && held.sliding;
  }
  for (size_t c = first; c < last; ++c) {
    ContactState& state = states_[contacts_[c].state];
    state.sliding = slides;
    // Anchors go when the pair slides; they stay through a flight (flown), and start again
    // where the contact is when friction could not take the slip back (restart_anchors).
    state.anchored = state.anchored && !slides;
    if (state.anchored && contacts_[c].capped) restart_anchors(state, located_[c]);
    state.flown = state.anchored && contacts_[c].lambda_normal == 0.0;
    if (contacts_[c].particle_contact < 0) continue;
    const ParticleContact& held = particle_contacts_.contacts()[contacts_[c].particle_contact];
    state.particle_force = held.force;
    state.friction_force = held.friction_force;
    state.sliding = held_touching && all_on_cone;
  }
  return last;
}

void ContactSolver::end_substep(bool end_of_interval) {
  // Particle contacts: the multiplier step λ ← max(0, λ − k C), once a substep, carried to the
  // next (once a sweep, it overshot: a grain on a plane at h = 1/60 s rang at ±100% of its weight).
  // Their friction's too, λ_t ← f_t, and whether each slides (particle_contacts.hpp).
  if (particle_steps_) {
    particle_contacts_.update_forces(model_.particles.x);
    if (bonds_) bonds_->take_particle_forces(particle_contacts_, model_.particles.x, h_);
  }
  double deepest = 0.0;
  collider_impulses_.resize(model_.colliders.size(), Vec3::Zero());
  substep_impulses_.assign(model_.colliders.size(), Vec3::Zero());
  located_.resize(contacts_.size());
  interval_time_ += h_;
  for (size_t first = 0; first < contacts_.size();) first = end_pair_substep(first, end_of_interval, deepest);
  statistics_.max_penetration = deepest;
  for (size_t c = 0; c < model_.colliders.size(); ++c) {
    Collider& collider = model_.colliders[c];
    if (yields(collider)) collider.yield.force = substep_impulses_[c].dot(collider.yield_axis) / h_;
    collider_impulses_[c] += substep_impulses_[c];
  }
  if (end_of_interval) {
    statistics_.collider_forces.resize(collider_impulses_.size());
    for (size_t c = 0; c < collider_impulses_.size(); ++c)
      statistics_.collider_forces[c] = collider_impulses_[c] / interval_time_;
    collider_impulses_.assign(collider_impulses_.size(), Vec3::Zero());
    interval_time_ = 0.0;
  }
  if (bonds_) update_bonds();
}

void ContactSolver::update_bonds() {
  bonds_->end_substep(h_);
  statistics_.bonds = bonds_->count();
  statistics_.bonds_broken = bonds_->broken();
}

/// What carries over between steps: the contacts' states (anchors, sliding, the forces held
/// in particle steps), the broad phase's sphere centres and time, the radii and their time,
/// the centres, boxes and motions of sleeping bodies (not recomputed while they sleep: a run
/// resumed with its parked grains' boxes left unset woke them), the collider impulses of the
/// interval, the statistics (the deepest penetration so far), the yielding colliders' offsets
/// and the bonds. The broad phase's pairs are not kept, since every step starts with a broad
/// phase (with them a 10,000-grain clump's checkpoint was 402 MB, without them 22.5 MB), and
/// the rest is rebuilt each substep.
template <class Self, class Archive>
void ContactSolver::transfer_state(Self& self, Archive& archive) {
  auto& s = self.statistics_;
  archive(self.collider_impulses_, self.interval_time_, self.states_, self.centre_now_, self.centre_start_,
          self.centre_at_broad_phase_, self.broad_phase_time_, self.radius_, self.radii_time_, self.centres_at_rest_,
          self.start_box_, self.motion_,
          s.candidates, s.contacts, s.max_penetration, s.bonds, s.bonds_broken, s.collider_forces);
  for (auto& collider : self.model_.colliders)
    archive(collider.yield.time, collider.yield.offset, collider.yield.rate, collider.yield.force);
  bool bonds = self.bonds_.has_value();
  archive(bonds);
  if (bonds != self.bonds_.has_value()) throw std::runtime_error("the state's cohesion does not match the model's");
  if (self.bonds_) {
    if constexpr (std::is_const_v<Self>) self.bonds_->save_state(archive);
    else self.bonds_->load_state(archive);
  }
}

void ContactSolver::save_state(StateWriter& out) const { transfer_state(*this, out); }
void ContactSolver::load_state(StateReader& in) { transfer_state(*this, in); }

}  // namespace rice::xpbd
