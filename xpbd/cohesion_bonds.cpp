// Forming, projecting and breaking cohesive bonds; see cohesion_bonds.hpp.
#include "xpbd/cohesion_bonds.hpp"

#include "xpbd/state_archive.hpp"

#include <algorithm>
#include <set>

namespace rice::xpbd {

void CohesionBonds::begin_substep(const Model& model, const std::vector<Touch>& touches, const Positions& x_previous) {
  sort_bonds();
  const size_t held = bonds_.size();  // sorted; the touches' keys are distinct
  const auto bonded = [&](const std::array<int, 4>& key) {
    const auto at = std::lower_bound(bonds_.begin(), bonds_.begin() + held, key,
                                     [](const Bond& bond, const std::array<int, 4>& k) { return bond.key < k; });
    return at != bonds_.begin() + held && at->key == key;
  };
  std::map<std::pair<int, int>, double> still_touching;
  for (const Touch& touch : touches) {
    const auto [a, b, sa, sb] = touch.key;
    const auto broken = broken_pairs_.find({a, b});
    if (broken != broken_pairs_.end() && broken->second < model.contact.bond_heal_time) {
      still_touching.insert(*broken);
      continue;
    }
    const Body& body_a = model.bodies[a];
    const Body& body_b = model.bodies[b];
    const double strength = std::min(body_a.bond_strength, body_b.bond_strength);
    if (!(strength > 0.0) || bonded(touch.key)) continue;
    bonds_.push_back({touch.key, material_coordinates(model, body_a, sa, touch.pa, &x_previous),
                      material_coordinates(model, body_b, sb, touch.pb, &x_previous), (touch.pa - touch.pb).norm(),
                      strength});
    sorted_ = false;
  }
  broken_pairs_ = std::move(still_touching);
  for (Bond& bond : bonds_) {
    bond.lambda = 0.0;
    bond.held = -1;
  }
}

void CohesionBonds::hold_in_particle_steps(const Model& model, ParticleContacts& terms) {
  const double compliance = model.contact.bond_compliance;
  if (!(compliance > 0.0)) return;  // a hard bond has no spring constant: it stays a projection
  // k = min(1/α, the particle terms' k): see particle_contacts.hpp.
  for (Bond& bond : bonds_) {
    const Body& a = model.bodies[bond.key[0]];
    const Body& b = model.bodies[bond.key[1]];
    if (a.kind != BodyKind::kSoft || b.kind != BodyKind::kSoft || (a.asleep && b.asleep)) continue;
    ParticleBond term;
    const auto add_sphere = [&](const Body& body, int s, double sign) {
      for (int k = 0; k < 4; ++k) {
        term.point.particles[term.point.size] = body.anchors[s].particles[k];
        term.point.weights[term.point.size++] = sign * body.anchors[s].weights[k];
      }
    };
    add_sphere(a, bond.key[2], 1.0);
    add_sphere(b, bond.key[3], -1.0);
    term.offset = bond.anchor_a - bond.anchor_b;  // soft material coordinates: offsets from the centres
    term.length = bond.length;
    term.stiffness = std::min(1.0 / compliance, model.contact.particle_stiffness);
    bond.held = static_cast<int>(terms.bonds().size());
    terms.add(term);
  }
}

void CohesionBonds::take_particle_forces(const ParticleContacts& terms, const Positions& x, double h) {
  for (Bond& bond : bonds_)
    if (bond.held >= 0) bond.lambda = -terms.bonds()[bond.held].pull(x) * h * h;
}

void CohesionBonds::project(Model& model, double h) {
  const double alpha_tilde = model.contact.bond_compliance / (h * h);
  for (Bond& bond : bonds_) {
    if (bond.held >= 0) continue;  // a term of the particles' steps
    const auto [ia, ib, sa, sb] = bond.key;
    const Body& a = model.bodies[ia];
    const Body& b = model.bodies[ib];
    const Vec3 pa = material_point(model, a, sa, bond.anchor_a);
    const Vec3 pb = material_point(model, b, sb, bond.anchor_b);
    const Vec3 d = pa - pb;
    const double distance = d.norm();
    const double C = distance - bond.length;
    if (!(C > 0.0)) continue;  // slack
    const Vec3 n = d / distance;
    const double w = inverse_mass_at(model, a, sa, pa, n) + inverse_mass_at(model, b, sb, pb, n);
    // Two sleeping bodies (w = 0): nothing can move, and the bond carries no force. Solved,
    // it would read its stretch over its compliance as a force and break a resting pair.
    if (!(w > 0.0)) continue;
    // XPBD eq. 18: Δλ = (−C − α̃λ) / (w + α̃), applied as −Δλ along n on a (towards b); a
    // bond only pulls, λ ≤ 0.
    const double delta = std::min((-C - alpha_tilde * bond.lambda) / (w + alpha_tilde), -bond.lambda);
    bond.lambda += delta;
    apply_impulse_at(model, a, sa, pa, delta * n);
    apply_impulse_at(model, b, sb, pb, -delta * n);
  }
}

void CohesionBonds::sort_bonds() {
  if (sorted_) return;
  std::sort(bonds_.begin(), bonds_.end(), [](const Bond& x, const Bond& y) { return x.key < y.key; });
  sorted_ = true;
}

void CohesionBonds::end_substep(double h) {
  sort_bonds();
  std::vector<Bond> kept;
  kept.reserve(bonds_.size());
  for (size_t first = 0; first < bonds_.size();) {
    size_t last = first;
    double force = 0.0;  // Σ|λ|/h² over the pair's bonds
    for (; last < bonds_.size() && bonds_[last].key[0] == bonds_[first].key[0] &&
           bonds_[last].key[1] == bonds_[first].key[1];
         ++last)
      force += -bonds_[last].lambda / (h * h);
    if (force <= bonds_[first].strength) {
      kept.insert(kept.end(), bonds_.begin() + first, bonds_.begin() + last);
    } else {
      ++broken_;
      broken_pairs_[{bonds_[first].key[0], bonds_[first].key[1]}] = 0.0;
    }
    first = last;
  }
  bonds_ = std::move(kept);
  for (auto& [pair, touched] : broken_pairs_) touched += h;
}

template <class Self, class Archive>
void CohesionBonds::transfer_state(Self& self, Archive& archive) {
  archive(self.bonds_, self.broken_pairs_, self.sorted_, self.broken_);
}

std::vector<int> CohesionBonds::bonded_neighbours(int bodies) const {
  std::set<std::pair<int, int>> pairs;
  for (const Bond& bond : bonds_) pairs.emplace(bond.key[0], bond.key[1]);
  std::vector<int> count(bodies, 0);
  for (const auto& [a, b] : pairs) {
    if (a >= 0 && a < bodies) ++count[a];
    if (b >= 0 && b < bodies) ++count[b];
  }
  return count;
}

void CohesionBonds::save_state(StateWriter& out) const { transfer_state(*this, out); }
void CohesionBonds::load_state(StateReader& in) { transfer_state(*this, in); }

}  // namespace rice::xpbd
