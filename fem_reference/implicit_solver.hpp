// The reference solver: backward Euler on the shared model (xpbd/model.hpp), one Newton solve
// (newton_solver.hpp) per step, plus a quasi-static mode. It minimises the incremental
// potential (Martin et al. 2011, "Example-based elastic materials"; Gast et al. 2015,
// "Optimization integrator for large time steps")
//
//   E(x) = ½‖x − x̂‖²_M − h² fᵀx + h² U(x) + h² Ψ(x),     x̂ = xⁿ + h vⁿ,        (1)
//   U = Σ ½ Cᵀα⁻¹C − U_rest,    Ψ = Σ β/(2h) (C(x) − C(xⁿ))² + Ψ^E,
//
// with f the gravity and external loads, then sets v = (x − xⁿ)/h. Ψ = h·D is the Rayleigh
// dissipation D = ½ ĊᵀβĊ times h, with Ċ ≈ (C(x) − C(xⁿ))/h; Ψ^E is the strain-rate damping
// of the tets that have it (strain_rate_damping_form.hpp).
//
// Correspondence with XPBD (Macklin et al. 2016, §4–5). XPBD's fixed point for K → ∞ solves
// eqs. (18), (26) with g = 0:  M(x − x̃) = ∇C(x)ᵀλ,  C + α̃λ + γ ∇C(x)(x − xⁿ) = 0, with
// α̃ = α/h², γ = αβ/h. Eliminating λ = −α̃⁻¹(C + γ∇CΔx):
//
//   M(x − x̃) + h² ∇C(x)ᵀα⁻¹C(x) + h ∇C(x)ᵀβ ∇C(x)Δx = 0,                       (2)
//
// which is backward Euler with the elastic force −∇U and the damping force −∇Cᵀβ Ċ,
// Ċ = ∇C(x)Δx / h evaluated at the new state. The stationarity condition of (1) is (2) with
// ∇C(x)Δx replaced by C(x) − C(xⁿ) = ∇C(x)Δx − ½ Δxᵀ∇²C Δx + O(|Δx|³). The replacement is
// needed because ∇C(x)ᵀβ∇C(x)Δx is not the gradient of any potential when ∇²C ≠ 0, and a
// Newton solver with line search needs one. Both are first-order discretisations of the same
// damping force; they differ by O(h β |∇²C| |v|²) per step, which vanishes for linear
// constraints and at small strain rates. The convergence study measures it (runs with β and
// without). Without damping (β = 0) (1) and (2) are the same equation.
//
// Quasi-static mode minimises U(x) − fᵀx. Pinned particles (w = 0) and rigid attachments
// (α = 0, held at their targets) have no DOFs. Contact with the ground plane and with
// half-space and sphere colliders is the barrier B of barrier_contact_form.hpp, added to U
// (frictionless; posed at the end of each step); soft bodies with collision spheres touch
// each other and half-space colliders through their spheres, as in XPBD
// (sphere_contact_form.hpp). A model with a rigid spring or volume constraint or another
// collider shape is rejected.
#pragma once

#include <memory>
#include <vector>

#include "fem_reference/barrier_contact_form.hpp"
#include "fem_reference/sphere_contact_form.hpp"
#include "fem_reference/constraint_potential_form.hpp"
#include "fem_reference/inertia_form.hpp"
#include "fem_reference/load_form.hpp"
#include "fem_reference/newton_solver.hpp"
#include "fem_reference/strain_rate_damping_form.hpp"
#include "xpbd/model.hpp"

namespace rice::fem {

struct ImplicitSettings {
  double time_step = 1e-3;  ///< h of one backward-Euler step [s]
  NewtonSettings newton;
};

class ImplicitSolver {
 public:
  /// Keeps a reference to the model. Throws std::invalid_argument for what it cannot solve.
  /// `contact` sets the barrier of the ground and colliders (barrier_contact_form.hpp).
  ImplicitSolver(xpbd::Model& model, const ImplicitSettings& settings, const BarrierSettings& contact = {});
  ~ImplicitSolver();

  /// One backward-Euler step of settings().time_step. Throws xpbd::SimulationError when
  /// Newton ends on a non-finite state; an unconverged solve is reported in report().
  void step();

  /// Moves the model to a minimum of U(x) − fᵀx (velocities set to zero). The collision
  /// spheres' radii are held at those of the start shape, or of `radii_shape` when given: a
  /// caller after the state where radii and shape agree, as XPBD's rest state (its radii follow
  /// the shape every substep), solves again with radii from the last solution until it stops
  /// moving.
  NewtonReport solve_static(const Positions* radii_shape = nullptr);

  /// The Newton report of the last step() or solve_static().
  const NewtonReport& report() const { return report_; }
  /// The contact barrier, or null when the model has no ground and no colliders.
  const BarrierContactForm* contact() const { return contact_.get(); }
  /// Contact between soft bodies' collision spheres, and of those spheres with half-space
  /// colliders (sphere_contact_form.hpp); null where the model has none.
  const SpherePairContactForm* sphere_pairs() const { return sphere_pairs_.get(); }
  const SpherePlaneContactForm* sphere_planes() const { return sphere_planes_.get(); }
  const ImplicitSettings& settings() const { return settings_; }

 private:
  void hold_rigid_attachments();
  /// Throws xpbd::SimulationError when x has a particle where the barrier is infinite.
  void require_outside_obstacles(const Positions& x, const char* what) const;
  void check(const char* what) const;

  xpbd::Model& model_;
  ImplicitSettings settings_;
  std::vector<bool> fixed_;
  std::vector<xpbd::Attachment> compliant_attachments_;
  InertiaForm inertia_;
  LoadForm loads_;
  /// U alone, for the quasi-static solve; U + Ψ per constraint type, for the time step.
  std::vector<std::unique_ptr<Form>> static_forms_;
  std::unique_ptr<ConstraintPotentialForm<NeoHookeanKernel>> step_neo_hookean_;
  std::unique_ptr<ConstraintPotentialForm<TetVolumeKernel>> step_volume_;
  std::unique_ptr<ConstraintPotentialForm<DistanceKernel>> step_distance_;
  std::unique_ptr<ConstraintPotentialForm<AttachmentKernel>> step_attachment_;
  std::unique_ptr<StrainRateDampingForm> step_strain_rate_damping_;
  std::unique_ptr<BarrierContactForm> contact_;
  std::unique_ptr<SpherePairContactForm> sphere_pairs_;
  std::unique_ptr<SpherePlaneContactForm> sphere_planes_;
  std::vector<Form*> contact_forms_;  ///< those of the three above that are on
  /// Poses the colliders at time t and takes the spheres' radii from the model's shape now.
  void prepare_contact(double t);
  std::unique_ptr<NewtonSolver> dynamic_, static_;
  NewtonReport report_;
  long step_ = 0;
};

}  // namespace rice::fem
