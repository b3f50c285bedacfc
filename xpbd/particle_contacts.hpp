// Contacts as terms of each particle's step, for vertex block descent
// (vertex_block_descent.hpp). A contact between collision spheres of two soft bodies, or of a
// soft body and a collider, with its normal n fixed over the substep (contact_solver.hpp) is
// linear in the particles, each sphere centre being c = Σ_k w_k x_k over its tet's corners:
//
//   C(x) = n·(c_a − c_b) − r_a − r_b      or      C(x) = n·(c_a − q) − r_a  (q on the collider)
//        = Σ_j a_j n·x_j − offset ≥ 0,   a_j = +w_j on a's corners, −w_j on b's.
//
// Each is held by an augmented Lagrangian (Giles et al. 2025, "Augmented Vertex Block
// Descent"): a force λ ≥ 0 and a stiffness k enter the step's potential as
//
//   ψ(C) = max(0, λ − k C)² / (2k),   ∇_{x_j} ψ = −max(0, λ − k C) a_j n,
//   ∇²_{x_j} ψ = k a_j² n nᵀ where λ − k C > 0,
//
// and after every substep λ ← max(0, λ − k C) (the method of multipliers, its inner solve the
// substep's sweeps). A fixed point has λ = max(0, λ − k C): either λ = 0 and C ≥ 0 (apart),
// or C = 0 and λ > 0, the contact force (touching, without overlap): the complementarity of a
// frictionless contact, whatever k. Within a substep the overlap is what the force λ leaves
// over, pushed back by k. λ carries over while the sphere pair stays a contact, so a resting
// grain starts each step with the force that holds it.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "xpbd/types.hpp"

namespace rice::xpbd {

struct ParticleContact {
  std::array<int, 8> particles{};   ///< the corners of a's tet, then of b's (collider: a's only)
  std::array<double, 8> weights{};  ///< a_j
  int size = 0;                     ///< 4 or 8
  Vec3 normal = Vec3::Zero();       ///< n
  double offset = 0.0;
  double force = 0.0;      ///< λ [N]
  double stiffness = 0.0;  ///< k [N/m]
  double value(const Positions& x) const;  ///< C(x) [m]
  /// max(0, λ − k C): the force it pushes with at C [N].
  double push_at(double C) const { return std::max(0.0, force - stiffness * C); }
  double push(const Positions& x) const { return push_at(value(x)); }
};

/// The contacts of a substep and, for each particle, which of them it is a corner of.
class ParticleContacts {
 public:
  void clear() { contacts_.clear(); }
  void add(const ParticleContact& contact) { contacts_.push_back(contact); }
  /// Builds the particle → contact index for `particle_count` particles; call after the adds.
  void index(int particle_count);
  /// λ ← max(0, λ − k C) for every contact, at x (the multiplier step).
  void update_forces(const Positions& x);

  std::vector<ParticleContact>& contacts() { return contacts_; }
  const std::vector<ParticleContact>& contacts() const { return contacts_; }
  bool empty() const { return contacts_.empty(); }
  /// Whether particle i is a corner of some contact.
  bool touches(int i) const { return first_[i] != first_[i + 1]; }
  /// Adds particle i's terms of Σ ψ at x to a gradient and Hessian (see the file comment).
  void add_particle_terms(const Positions& x, int i, Vec3& gradient, Mat3& hessian) const;
  /// Particle i's terms of Σ ψ at x with x_i moved by `offset`.
  double particle_energy(const Positions& x, int i, const Vec3& offset) const;

 private:
  struct Entry {
    int contact, slot;
  };
  std::vector<ParticleContact> contacts_;
  std::vector<int> first_{0};  ///< CSR: particle i's entries are entries_[first_[i] .. first_[i + 1])
  std::vector<Entry> entries_;
};

}  // namespace rice::xpbd
