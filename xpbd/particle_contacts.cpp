// Contacts as terms of each particle's step; see particle_contacts.hpp.
#include "xpbd/particle_contacts.hpp"

namespace rice::xpbd {

double ParticleContact::value(const Positions& x) const {
  Vec3 sum = Vec3::Zero();
  for (int j = 0; j < size; ++j) sum += weights[j] * x.row(particles[j]).transpose();
  return normal.dot(sum) - offset;
}

void ParticleContacts::index(int particle_count) {
  first_.assign(particle_count + 1, 0);
  for (const ParticleContact& c : contacts_)
    for (int j = 0; j < c.size; ++j) ++first_[c.particles[j] + 1];
  for (int i = 0; i < particle_count; ++i) first_[i + 1] += first_[i];
  entries_.resize(first_.back());
  std::vector<int> next(first_.begin(), first_.end() - 1);
  for (size_t c = 0; c < contacts_.size(); ++c)
    for (int j = 0; j < contacts_[c].size; ++j) entries_[next[contacts_[c].particles[j]]++] = {static_cast<int>(c), j};
}

void ParticleContacts::update_forces(const Positions& x) {
  for (ParticleContact& c : contacts_) c.force = c.push(x);
}

void ParticleContacts::add_particle_terms(const Positions& x, int i, Vec3& gradient, Mat3& hessian) const {
  for (int e = first_[i]; e < first_[i + 1]; ++e) {
    const ParticleContact& c = contacts_[entries_[e].contact];
    const double push = c.push(x);
    if (push == 0.0) continue;
    const double a = c.weights[entries_[e].slot];
    gradient -= push * a * c.normal;
    hessian += c.stiffness * a * a * c.normal * c.normal.transpose();
  }
}

double ParticleContacts::particle_energy(const Positions& x, int i, const Vec3& offset) const {
  double energy = 0.0;
  for (int e = first_[i]; e < first_[i + 1]; ++e) {
    const ParticleContact& c = contacts_[entries_[e].contact];
    const double push = c.push_at(c.value(x) + c.weights[entries_[e].slot] * c.normal.dot(offset));
    energy += 0.5 * push * push / c.stiffness;
  }
  return energy;
}

}  // namespace rice::xpbd
