// Contacts, their friction and cohesive bonds as terms of each particle's step, for vertex
// block descent (vertex_block_descent.hpp). Every term acts on a point that is linear in the
// particles: a collision sphere's centre is c = Σ_k w_k x_k over its tet's corners, so the
// relative position of two spheres (or of a sphere and a collider point q) is
//
//   L(x) = Σ_j a_j x_j,   a_j = +w_j on a's corners, −w_j on b's.
//
// Contact. With the normal n fixed over the substep (contact_solver.hpp),
//
//   C(x) = n·L(x) − offset ≥ 0,
//
// held by an augmented Lagrangian (Giles et al. 2025, "Augmented Vertex Block Descent"): a
// force λ ≥ 0 and a stiffness k enter the step's potential as
//
//   ψ_n = max(0, λ − k C)² / (2k),   ∇_{x_j} ψ_n = −f_n a_j n,   f_n = max(0, λ − k C),
//   ∇²_{x_j} ψ_n = k a_j² n nᵀ where f_n > 0,
//
// and after every substep λ ← f_n(x) (the method of multipliers, its inner solve the
// substep's sweeps). A fixed point has λ = max(0, λ − k C): either λ = 0 and C ≥ 0 (apart),
// or C = 0 and λ > 0, the contact force (touching, without overlap), whatever k.
//
// Friction (AVBD §4.3 with the normal force lagged one sweep, as IPC lags it: Li et al.
// 2020 §5). The slip of the contact points over the substep is s(x) = P (L(x) − r), P = I − n nᵀ
// and r = L(x_start), plus the collider point's motion over the substep against a collider.
// A tangential force λ_t (in the tangent plane) and the same k give
//
//   u = λ_t − k s,   f_t = u if |u| ≤ m, else m u/|u|,   m = μ f_n,
//   ψ_t = |u|²/(2k) if |u| ≤ m, else (m|u| − m²/2)/k            (a Huber function of u),
//   ∇_{x_j} ψ_t = −a_j f_t,
//   ∇²_{x_j} ψ_t = k a_j² P inside the cone, k a_j² (m/|u|)(P − û ûᵀ) on it.
//
// (With k a_j² P on the cone too, a majoriser, a sliding particle's step was held to the
// driving force over k: a grain on a plane tilted past μ_s stopped after 0.7 mm.)
//
// f_n (hence m) is taken once per sweep (set_friction_bounds) from the contact's normal force,
// so within a sweep ψ_t is a fixed convex function and every particle step lowers the step's
// potential. After each substep λ_t ← f_t(x) with m from the new normal force, and the
// contact records whether f_t lay on the cone; the contact solver lets a body pair's contacts
// slide in the next substep (μ = μ_k) when all of them did, else stick (μ = μ_s). A fixed
// point inside the cone has s = 0: a sticking contact does not creep.
//
// Bond. A cohesive bond (cohesion_bonds.hpp) is a spring of stiffness k* between two anchors
// d(x) = L(x) + e (e the anchors' offsets from their spheres' centres) that only pulls:
//
//   C_b = |d| − d₀,   ψ_b = ½ k* max(0, C_b)²,   ∇_{x_j} ψ_b = a_j k* C_b d̂,
//   ∇²_{x_j} ψ_b = a_j² k* (d̂ d̂ᵀ + C_b/|d| (I − d̂ d̂ᵀ))   where C_b > 0.
//
// k* = min(1/α, k), the bond's own spring constant capped at the contacts' k, with no
// multiplier (AVBD caps a finite stiffness the same way, though it ramps towards it). Its force
// k* C_b is what breaks it. (At 1/α = 1e4 N/m, a period of 0.1 ms against steps of 3–17 ms,
// grains rang on their bonds under 5–10 sweeps: bonds broke at 29% of their strength, a
// resting sticky pile stayed awake at 1e-8 J, and a 100-grain sticky pour had 4504 pair
// breaks. Capped at 300 N/m: 2052 breaks, and the pile sleeps by 5.5 s.)
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "xpbd/types.hpp"

namespace rice::xpbd {

/// L(x) = Σ_j a_j x_j over up to eight particles: a's sphere's corners, then b's.
struct LinearPoint {
  std::array<int, 8> particles{};
  std::array<double, 8> weights{};  ///< a_j
  int size = 0;                     ///< 4 or 8
  Vec3 at(const Positions& x) const;
};

struct ParticleContact {
  LinearPoint point;           ///< L: the two spheres' centres' difference (collider: a's centre)
  Vec3 normal = Vec3::Zero();  ///< n
  double offset = 0.0;
  double force = 0.0;      ///< λ [N]
  double stiffness = 0.0;  ///< k [N/m]
  double friction = 0.0;   ///< μ of this substep (0: no friction term)
  Vec3 slip_origin = Vec3::Zero();     ///< r [m]
  Vec3 friction_force = Vec3::Zero();  ///< λ_t [N], in the tangent plane
  double friction_bound = 0.0;         ///< m = μ f_n of this sweep [N]
  bool sliding = false;                ///< f_t lay on the cone at the last multiplier step
  double value(const Positions& x) const { return normal.dot(point.at(x)) - offset; }  ///< C(x) [m]
  /// max(0, λ − k C): the force it pushes with at C [N].
  double push_at(double C) const { return std::max(0.0, force - stiffness * C); }
  double push(const Positions& x) const { return push_at(value(x)); }
  /// u = λ_t − k s for L(x) = `L`.
  Vec3 friction_trial(const Vec3& L) const;
  /// f_t for L(x) = `L`, with the bound m.
  Vec3 friction_at(const Vec3& L, double bound) const;
};

struct ParticleBond {
  LinearPoint point;           ///< L: a's sphere centre minus b's
  Vec3 offset = Vec3::Zero();  ///< e
  double length = 0.0;         ///< d₀ [m]
  double stiffness = 0.0;      ///< k* [N/m]
  /// k* max(0, |d| − d₀): the force it pulls with at d [N].
  double pull_at(const Vec3& d) const { return stiffness * std::max(0.0, d.norm() - length); }
  double pull(const Positions& x) const { return pull_at(point.at(x) + offset); }
};

/// The contacts and bonds of a substep and, for each particle and each body, which of them
/// it takes part in.
class ParticleContacts {
 public:
  void clear();
  void add(const ParticleContact& contact) { contacts_.push_back(contact); }
  void add(const ParticleBond& bond) { bonds_.push_back(bond); }
  /// Builds the particle → term and body → term indices; call after the adds. A term's corners
  /// 0–3 and 4–7 each lie on one body, body_of_particle[their first] (−1: none; the vector may
  /// be empty for no bodies).
  void index(int particle_count, const std::vector<int>& body_of_particle = {}, int body_count = 0);
  /// Once per sweep, before it: m = μ f_n of every contact with friction, at x.
  void set_friction_bounds(const Positions& x);
  /// The multiplier step at x, once per substep: λ ← max(0, λ − k C), then λ_t ← f_t with
  /// m = μ λ, and whether each contact slides.
  void update_forces(const Positions& x);

  std::vector<ParticleContact>& contacts() { return contacts_; }
  const std::vector<ParticleContact>& contacts() const { return contacts_; }
  const std::vector<ParticleBond>& bonds() const { return bonds_; }
  bool empty() const { return contacts_.empty() && bonds_.empty(); }
  /// Whether particle i is a corner of some term.
  bool touches(int i) const { return first_[i] != first_[i + 1]; }
  /// Adds particle i's terms of Σ ψ at x to a gradient and Hessian (see the file comment).
  void add_particle_terms(const Positions& x, int i, Vec3& gradient, Mat3& hessian) const;
  /// Particle i's terms of Σ ψ at x with x_i moved by `offset`.
  double particle_energy(const Positions& x, int i, const Vec3& offset) const;
  /// The same for a translation of body b as a whole: its terms' derivatives with respect to
  /// it (weights A = Σ a_j over its corners of each term), and their energy with it shifted.
  void add_body_terms(const Positions& x, int b, Vec3& gradient, Mat3& hessian) const;
  double body_energy(const Positions& x, int b, const Vec3& shift) const;

 private:
  struct Entry {
    int term;       ///< a contact, or −1 − the bond
    double weight;  ///< ∂L/∂(what moves): a_j for a particle, Σ a_j over its corners for a body
  };
  void add_terms(const Entry* begin, const Entry* end, const Positions& x, Vec3& gradient, Mat3& hessian) const;
  double energy(const Entry* begin, const Entry* end, const Positions& x, const Vec3& shift) const;
  std::vector<ParticleContact> contacts_;
  std::vector<ParticleBond> bonds_;
  std::vector<int> first_{0};  ///< CSR: particle i's entries are entries_[first_[i] .. first_[i + 1])
  std::vector<Entry> entries_;
  std::vector<int> first_body_{0};  ///< CSR likewise for bodies
  std::vector<Entry> body_entries_;
};

}  // namespace rice::xpbd
