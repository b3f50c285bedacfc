// Frictionless contact of particles against the ground plane and analytic colliders (half-spaces
// and spheres) as a smooth barrier in the reference solver's energy (Li et al. 2020,
// "Incremental Potential Contact", eq. 6):
//
//   B(x) = κ Σ_i Σ_o b(d_o(x_i)),   b(d) = −(d − d̂)² ln(d / d̂) for 0 < d < d̂, 0 beyond,
//
// d_o the signed distance of particle i to obstacle o, d̂ the distance at which contact starts,
// κ its stiffness [N/m]. b is C² at d̂ and infinite at d = 0, so a Newton step whose line search
// starts below max_step() (no particle moves farther than 90% of its distance: d is
// 1-Lipschitz, so nothing crosses) and rejects infinite energy never lets a particle through.
// In a time step the barrier is weighted like the elastic energy (h²), so κ b'(d) is a force.
//
// As in XPBD, the ground meets every particle, while a soft body with collision spheres meets
// colliders through its spheres (sphere_contact_form.hpp), not through its particles.
#pragma once

#include <vector>

#include "fem_reference/element_form.hpp"
#include "xpbd/model.hpp"

namespace rice::fem {

/// The barrier's parameters.
struct BarrierSettings {
  double activation_distance = 1e-4;  ///< d̂ [m]
  double stiffness = 1e3;             ///< κ [N/m]
};

/// b(d), b'(d), b''(d) of the IPC barrier with activation distance d̂ (zero for d ≥ d̂).
struct BarrierValue {
  double value, first, second;
};
BarrierValue ipc_barrier(double d, double dhat);

class BarrierContactForm final : public ElementForm<1> {
 public:
  /// Obstacles: the model's ground plane and its half-space and sphere colliders (posed at
  /// time 0 until set_time; the form keeps pointers to the colliders); one element per
  /// particle with inverse mass > 0. Throws
  /// std::invalid_argument for a collider of another shape or settings that are not positive.
  BarrierContactForm(const xpbd::Model& model, const BarrierSettings& settings);

  /// Poses the colliders at time t (their keyframed motion).
  void set_time(double t);

  std::string name() const override { return "barrier contact"; }
  int element_count() const override { return static_cast<int>(particles_.size()); }
  Particles element_particles(int e) const override { return {particles_[e]}; }
  double element_value(int e, const LocalVector& x) const override;
  LocalVector element_gradient(int e, const LocalVector& x) const override;
  LocalMatrix element_hessian(int e, const LocalVector& x, bool project) const override;
  double max_step(const Positions& x, const Positions& dx) const override;

  /// Σ of the barrier forces −∇B on all particles from obstacle o (in the order: ground
  /// first, then the colliders that are obstacles) [N].
  xpbd::Vec3 contact_force(const Positions& x, int obstacle) const;
  int obstacle_count() const { return static_cast<int>(obstacles_.size()); }

 private:
  struct Obstacle {
    const xpbd::Collider* collider = nullptr;  ///< null: the ground plane
    bool sphere = false;
    xpbd::Vec3 normal = xpbd::Vec3::UnitZ();  ///< plane
    double offset = 0.0;                       ///< plane: n·x = offset on its surface
    xpbd::Vec3 centre = xpbd::Vec3::Zero();   ///< sphere
    double radius = 0.0;
  };
  /// Signed distance of a point to an obstacle, its gradient and Hessian.
  struct Distance {
    double d;
    xpbd::Vec3 gradient;
    xpbd::Mat3 hessian;
  };
  static Distance distance(const Obstacle& o, const xpbd::Vec3& p);

  /// Whether obstacle o acts on element (particle) e.
  bool acts_on(const Obstacle& o, int e) const { return !o.collider || meets_colliders_[e]; }

  BarrierSettings settings_;
  std::vector<int> particles_;
  std::vector<char> meets_colliders_;  ///< per element: its particle is in no body with spheres
  std::vector<Obstacle> obstacles_;
};

}  // namespace rice::fem
