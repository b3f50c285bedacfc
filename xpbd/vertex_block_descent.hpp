// Vertex block descent (Chen, Macklin et al. 2024, "Vertex Block Descent") on the Neo-Hookean
// tets of the shared model: Gauss–Seidel over particles on the backward-Euler incremental
// potential of one step of h,
//
//   E(x) = Σ_i m_i/(2h²) ‖x_i − y_i‖² + Σ_e [U_e(x) + Ψ^C_e(x) + Ψ^E_e(x)],               (1)
//
// y the inertial prediction, U_e = ½ Cᵀα⁻¹C − U_rest the stable Neo-Hookean pair (the same
// constraint kernels as XPBD and the reference), Ψ^C_e = Σ_r β_r/(2h) (C_r(x) − C_r(xⁿ))² its
// constraint Rayleigh damping as the reference writes it (fem_reference/implicit_solver.hpp),
// Ψ^E_e the strain-rate damping (strain_rate_damping.hpp). Each particle in turn takes one
// Newton step on E in its own three coordinates, the others held (VBD eqs. 7–9):
//
//   H_i Δx_i = −∇_i E,    H_i = m_i/h² I + Σ_e ∂²E_e/∂x_i².
//
// Particles of one colour share no tet and move in parallel; a fixed point is a stationary
// point of E, i.e. the reference's backward-Euler step. In one particle's coordinates E is a
// convex quadratic (‖F‖² is, det F is affine in them: μV‖b‖² I and λV (cof F b)(cof F b)ᵀ
// are its Hessian blocks) unless the constraints' Rayleigh damping is on: its C_D term can
// make H_i indefinite, and then H_i − m_i/h² I is projected onto the PSD cone and a step that
// would raise E is halved until it does not. Every sweep lowers E.
//
// Contacts between soft bodies' collision spheres, and of those with colliders, are terms of
// E held by an augmented Lagrangian, with their Coulomb friction (a bounded tangential
// multiplier) and the cohesive bonds between soft bodies (springs that only pull;
// particle_contacts.hpp), so the sweeps' fixed point is the step with its contact, friction
// and bond forces, and no sweep adds energy through a projection after it.
//
// Compliant attachments are springs ½‖x_i − p‖²/α in E (the reference's potential for them);
// those with α = 0 stay projections after each sweep (solver.cpp).
//
// A ground plane (Model::ground) is a constraint of each particle's step. When the Newton
// step would end below the plane, the normal force f_n is that of the step's minimiser on the
// plane (one multiplier, closed form); the particle then sticks where it was at the step's
// start (on the plane) when the tangential force that needs, f_t of f = HΔ + g, lies in the
// cone |f_t| ≤ μ_s f_n, and otherwise slides on the plane against kinetic friction μ_k f_n
// along f_t. (Taking f_n from the sticking reaction instead, an anisotropic H made it negative
// at load-bearing particles, which then slid without friction: a grain kept circling at
// 6 mm/s.) Handled after the sweep instead, the ground would move particles that the sweep's
// later particles had already answered, and the sweeps' fixed point would not be the rest
// state (a grain resting at h = 1/60 s stood 10% taller with 20 sweeps).
//
// Each sweep ends with a step of every soft body as a whole (body_step): per-particle
// Gauss–Seidel moves a body's particles one at a time against their tets, which hold them
// within (m/h²)/k_tet ≈ 1e-3 of a translation per sweep, so a body pushed across the slope of
// what holds it could hardly move. (A grain on a plane tilted past μ_s accelerated at 0.005
// m/s², where g(sin θ − μ_k cos θ) is 1.29.) A translation δ of all of a body's particles
// leaves its tets' terms unchanged (F, hence U and both dampings, are translation-invariant),
// so its Newton step needs only inertia, springs and the contact terms:
//
//   (M_b/h² I + Σ_t A_t² ∇²ψ_t) δ = −(Σ_i m_i/h² (x_i − y_i) + Σ_i ∇springs + Σ_t A_t ∇ψ_t),
//
// A_t the sum of the term's weights on the body's corners; the step is halved until it does
// not raise E. Bodies take it one after another, after the particles (taken before them, it
// left a grain sliding down a plane hopping 0.6 mm, at 3% of its acceleration); it is skipped with a ground plane (whose
// friction lives in the particles' steps) and for bodies with pinned or sleeping particles.
//
// The solver (solver.hpp) runs K sweeps per substep for Method::kVbd, updating the contacts'
// forces after each.
#pragma once

#include <Eigen/Cholesky>
#include <vector>

#include "xpbd/graph_coloring.hpp"
#include "xpbd/model.hpp"
#include "xpbd/particle_contacts.hpp"

namespace rice::xpbd {

class VertexBlockDescent {
 public:
  /// Incidence of particles and tets and the particle colouring; build again when the model's
  /// tets change.
  explicit VertexBlockDescent(const Model& model);

  /// Records what the potential of a step from `x_start` needs: C(xⁿ) per tet for Ψ^C and Fⁿ
  /// for Ψ^E (only where those damping terms are on). Keeps a reference to x_start.
  void begin_step(const Model& model, const Positions& x_start, double h);

  /// One Gauss–Seidel sweep over the particles of tets, colour by colour. Pinned particles
  /// (w = 0) and those marked in `frozen` (sleeping bodies; may be empty) stay.
  /// `contacts` (may be null): contacts held in the particles' steps (particle_contacts.hpp);
  /// their particles, which a colour may share through them, are visited one after another
  /// after the rest of their colour.
  void sweep(Model& model, const Positions& y, bool parallel, const std::vector<char>& frozen,
             const ParticleContacts* contacts = nullptr) const;

 private:
  struct Corner {
    int tet;
    int k;  ///< the particle's corner in the tet, 0..3
  };
  /// Soft body b's Newton step as a whole (see the file comment).
  void body_step(Model& model, const Positions& y, int b, const ParticleContacts* contacts) const;
  /// One particle's Newton step.
  void solve_particle(Model& model, const Positions& y, int i, const ParticleContacts* contacts) const;
  /// The terms of E that involve particle i, with x_i at `xi` (up to constants).
  double particle_energy(const Model& model, const Positions& y, int i, const Vec3& xi,
                         const ParticleContacts* contacts) const;
  /// Particle i's step when its Newton step would end below the ground, with Coulomb friction
  /// in force terms on its local quadratic q(Δ) = ½ΔᵀHΔ + gᵀΔ (H = `H`, factored in `newton`).
  static Vec3 ground_contact_step(const GroundPlane& ground, const Vec3& x, const Vec3& x_start, const Mat3& H,
                                  const Eigen::LLT<Mat3>& newton, const Vec3& g);

  std::vector<int> first_corner_;  ///< CSR: particle i's corners are corners_[first_corner_[i] .. [i + 1])
  /// Compliant attachments (α > 0) as springs ½‖x_i − p‖²/α of E: particle i's are
  /// springs_[first_spring_[i] .. [i + 1]), indices into Model::attachments.
  std::vector<int> first_spring_, springs_;
  std::vector<Corner> corners_;
  std::vector<int> soft_bodies_;  ///< Model::bodies that are soft
  Coloring coloring_;  ///< particles of tets grouped so that no two of a colour share a tet
  std::vector<Vec2> C_start_;
  std::vector<Mat3> F_start_;
  const Positions* x_start_ = nullptr;
  double h_ = 0.0;
  bool constraint_damping_ = false, strain_rate_damping_ = false;
};

}  // namespace rice::xpbd
