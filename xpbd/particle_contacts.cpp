// Contacts, friction and bonds as terms of each particle's step; see particle_contacts.hpp.
#include "xpbd/particle_contacts.hpp"

#include <cmath>

namespace rice::xpbd {
namespace {

/// ψ_t of a trial force u under the bound m (the Huber function of the file comment).
double friction_energy(const Vec3& u, double bound, double k) {
  const double norm = u.norm();
  if (norm <= bound) return 0.5 * norm * norm / k;
  return (bound * norm - 0.5 * bound * bound) / k;
}

/// A term's gradient and Hessian with respect to its point L.
struct PointDerivatives {
  Vec3 gradient = Vec3::Zero();
  Mat3 hessian = Mat3::Zero();
};

PointDerivatives contact_derivatives(const ParticleContact& c, const Vec3& L) {
  PointDerivatives d;
  const double push = c.push_at(c.normal.dot(L) - c.offset);
  if (push > 0.0) {
    d.gradient = -push * c.normal;
    d.hessian = c.stiffness * c.normal * c.normal.transpose();
  }
  if (!(c.friction_bound > 0.0)) return d;
  // −f_t, and k ∂f_t/∂u P: k P inside the cone, k (m/|u|)(P − û ûᵀ) on it.
  const Vec3 u = c.friction_trial(L);
  const double norm = u.norm();
  const Mat3 P = Mat3::Identity() - c.normal * c.normal.transpose();
  if (norm <= c.friction_bound) {
    d.gradient -= u;
    d.hessian += c.stiffness * P;
  } else {
    const Vec3 direction = u / norm;
    d.gradient -= c.friction_bound * direction;
    d.hessian += c.stiffness * c.friction_bound / norm * (P - direction * direction.transpose());
  }
  return d;
}

double contact_energy(const ParticleContact& c, const Vec3& L) {
  const double push = c.push_at(c.normal.dot(L) - c.offset);
  double energy = 0.5 * push * push / c.stiffness;
  if (c.friction_bound > 0.0) energy += friction_energy(c.friction_trial(L), c.friction_bound, c.stiffness);
  return energy;
}

PointDerivatives bond_derivatives(const ParticleBond& b, const Vec3& L) {
  PointDerivatives d;
  const Vec3 r = L + b.offset;
  const double pull = b.pull_at(r);
  if (pull == 0.0) return d;
  const double distance = r.norm();
  const Vec3 n = r / distance;
  d.gradient = pull * n;
  d.hessian = b.stiffness * n * n.transpose() + pull / distance * (Mat3::Identity() - n * n.transpose());
  return d;
}

double bond_energy(const ParticleBond& b, const Vec3& L) {
  const double pull = b.pull_at(L + b.offset);
  return 0.5 * pull * pull / b.stiffness;
}

}  // namespace

Vec3 LinearPoint::at(const Positions& x) const {
  Vec3 sum = Vec3::Zero();
  for (int j = 0; j < size; ++j) sum += weights[j] * x.row(particles[j]).transpose();
  return sum;
}

Vec3 ParticleContact::friction_trial(const Vec3& L) const {
  const Vec3 d = L - slip_origin;
  return friction_force - stiffness * (d - normal.dot(d) * normal);
}

Vec3 ParticleContact::friction_at(const Vec3& L, double bound) const {
  const Vec3 u = friction_trial(L);
  const double norm = u.norm();
  return norm <= bound ? u : Vec3(bound / norm * u);
}

void ParticleContacts::clear() {
  contacts_.clear();
  bonds_.clear();
}

void ParticleContacts::index(int particle_count, const std::vector<int>& body_of_particle, int body_count) {
  // A term's entry for particle j has weight a_j; for a body, the sum of its corners' weights.
  const auto for_each_term = [&](const auto& visit) {
    for (size_t c = 0; c < contacts_.size(); ++c) visit(contacts_[c].point, static_cast<int>(c));
    for (size_t b = 0; b < bonds_.size(); ++b) visit(bonds_[b].point, -1 - static_cast<int>(b));
  };
  const auto body_of = [&](int particle) { return body_of_particle.empty() ? -1 : body_of_particle[particle]; };
  first_.assign(particle_count + 1, 0);
  first_body_.assign(body_count + 1, 0);
  for_each_term([&](const LinearPoint& p, int) {
    for (int j = 0; j < p.size; ++j) ++first_[p.particles[j] + 1];
    for (int j = 0; j < p.size; j += 4)
      if (body_of(p.particles[j]) >= 0) ++first_body_[body_of(p.particles[j]) + 1];
  });
  for (int i = 0; i < particle_count; ++i) first_[i + 1] += first_[i];
  for (int b = 0; b < body_count; ++b) first_body_[b + 1] += first_body_[b];
  entries_.resize(first_.back());
  body_entries_.resize(first_body_.back());
  std::vector<int> next(first_.begin(), first_.end() - 1), next_body(first_body_.begin(), first_body_.end() - 1);
  for_each_term([&](const LinearPoint& p, int term) {
    for (int j = 0; j < p.size; ++j) entries_[next[p.particles[j]]++] = {term, p.weights[j]};
    for (int j = 0; j < p.size; j += 4) {
      if (body_of(p.particles[j]) < 0) continue;
      const double sum = p.weights[j] + p.weights[j + 1] + p.weights[j + 2] + p.weights[j + 3];
      body_entries_[next_body[body_of(p.particles[j])]++] = {term, sum};
    }
  });
}

void ParticleContacts::set_friction_bounds(const Positions& x) {
  for (ParticleContact& c : contacts_)
    if (c.friction > 0.0) c.friction_bound = c.friction * c.push(x);
}

void ParticleContacts::update_forces(const Positions& x) {
  for (ParticleContact& c : contacts_) {
    const Vec3 L = c.point.at(x);
    c.force = c.push_at(c.normal.dot(L) - c.offset);
    if (c.friction == 0.0) continue;
    c.friction_bound = c.friction * c.force;
    const Vec3 u = c.friction_trial(L);
    c.sliding = u.norm() > c.friction_bound;
    c.friction_force = c.friction_at(L, c.friction_bound);
  }
}

void ParticleContacts::add_terms(const Entry* begin, const Entry* end, const Positions& x, Vec3& gradient,
                                 Mat3& hessian) const {
  for (const Entry* e = begin; e != end; ++e) {
    const PointDerivatives d = e->term < 0 ? bond_derivatives(bonds_[-1 - e->term], bonds_[-1 - e->term].point.at(x))
                                           : contact_derivatives(contacts_[e->term], contacts_[e->term].point.at(x));
    gradient += e->weight * d.gradient;
    hessian += e->weight * e->weight * d.hessian;
  }
}

double ParticleContacts::energy(const Entry* begin, const Entry* end, const Positions& x, const Vec3& shift) const {
  double energy = 0.0;
  for (const Entry* e = begin; e != end; ++e) {
    if (e->term < 0) {
      const ParticleBond& b = bonds_[-1 - e->term];
      energy += bond_energy(b, b.point.at(x) + e->weight * shift);
    } else {
      const ParticleContact& c = contacts_[e->term];
      energy += contact_energy(c, c.point.at(x) + e->weight * shift);
    }
  }
  return energy;
}

void ParticleContacts::add_particle_terms(const Positions& x, int i, Vec3& gradient, Mat3& hessian) const {
  add_terms(entries_.data() + first_[i], entries_.data() + first_[i + 1], x, gradient, hessian);
}

double ParticleContacts::particle_energy(const Positions& x, int i, const Vec3& offset) const {
  return energy(entries_.data() + first_[i], entries_.data() + first_[i + 1], x, offset);
}

void ParticleContacts::add_body_terms(const Positions& x, int b, Vec3& gradient, Mat3& hessian) const {
  add_terms(body_entries_.data() + first_body_[b], body_entries_.data() + first_body_[b + 1], x, gradient, hessian);
}

double ParticleContacts::body_energy(const Positions& x, int b, const Vec3& shift) const {
  return energy(body_entries_.data() + first_body_[b], body_entries_.data() + first_body_[b + 1], x, shift);
}

}  // namespace rice::xpbd
