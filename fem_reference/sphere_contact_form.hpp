// Frictionless contact through the collision spheres of soft bodies (xpbd/body.hpp), the
// geometry XPBD's contact solver uses (xpbd/contact_solver.hpp), as the IPC barrier of
// barrier_contact_form.hpp. A soft body's sphere s has its centre embedded in a tet,
// c_s = Σ_k w_k x_k over the tet's corners, and for spheres a and b of two bodies and a
// half-space n·x ≥ o:
//
//   d_ab = ‖c_a − c_b‖ − r_a − r_b,        d_a = n·c_a − o − r_a,
//
// ∂d/∂x_k = ±w_k n (n = (c_a − c_b)/‖c_a − c_b‖, or the plane's normal), and for a pair
// ∂²d/∂x_j∂x_k = ±w_j w_k (I − n nᵀ)/‖c_a − c_b‖. The element's energy is κ b(d).
//
// The radii r = r₀ min(1, σ_min(F)) of xpbd::sphere_radius are held while a Newton solve runs
// (set_radii; XPBD holds them over a substep): a solve then has a smooth potential.
//
// Elements: every sphere pair of two different soft bodies and every sphere with every
// half-space collider (posed at the time set_time gives): O(n²) pairs, for the few-body
// validation scenes it is written for, not for piles.
#pragma once

#include <array>
#include <vector>

#include "fem_reference/barrier_contact_form.hpp"
#include "fem_reference/element_form.hpp"
#include "xpbd/model.hpp"

namespace rice::fem {

/// A collision sphere as the reference sees it: corners and weights of its centre, its radius.
struct EmbeddedSphere {
  std::array<int, 4> particles;
  Eigen::Vector4d weights;
  double radius;
};

/// The soft bodies' collision spheres of `model`, radii as xpbd::sphere_radius gives them now;
/// `body_of[s]` is sphere s's body.
std::vector<EmbeddedSphere> embedded_spheres(const xpbd::Model& model, std::vector<int>* body_of = nullptr);

/// Sphere pairs of two different bodies.
class SpherePairContactForm final : public ElementForm<8> {
 public:
  SpherePairContactForm(const xpbd::Model& model, const BarrierSettings& settings);

  /// Takes the radii from the model's current shape (xpbd::sphere_radius).
  void set_radii(const xpbd::Model& model);

  std::string name() const override { return "sphere pair contact"; }
  int element_count() const override { return static_cast<int>(pairs_.size()); }
  Particles element_particles(int e) const override;
  double element_value(int e, const LocalVector& x) const override;
  LocalVector element_gradient(int e, const LocalVector& x) const override;
  LocalMatrix element_hessian(int e, const LocalVector& x, bool project) const override;
  double max_step(const Positions& x, const Positions& dx) const override;

  /// Σ of −∇B on the particles of `body` from the other bodies' spheres [N].
  xpbd::Vec3 force_on_body(const Positions& x, int body) const;

 private:
  struct Gap {
    double d;
    xpbd::Vec3 normal;  ///< from b's centre to a's
    double length;      ///< ‖c_a − c_b‖
  };
  Gap gap(int e, const LocalVector& x) const;

  BarrierSettings settings_;
  std::vector<EmbeddedSphere> spheres_;
  std::vector<int> body_of_;
  std::vector<std::array<int, 2>> pairs_;  ///< sphere indices, a's body < b's body
};

/// Spheres against the half-space colliders.
class SpherePlaneContactForm final : public ElementForm<4> {
 public:
  /// Throws std::invalid_argument when the model has colliders of another shape.
  SpherePlaneContactForm(const xpbd::Model& model, const BarrierSettings& settings);

  void set_radii(const xpbd::Model& model);
  /// Poses the half-spaces at time t.
  void set_time(double t);

  std::string name() const override { return "sphere plane contact"; }
  int element_count() const override { return static_cast<int>(elements_.size()); }
  Particles element_particles(int e) const override { return spheres_[elements_[e][0]].particles; }
  double element_value(int e, const LocalVector& x) const override;
  LocalVector element_gradient(int e, const LocalVector& x) const override;
  LocalMatrix element_hessian(int e, const LocalVector& x, bool project) const override;
  double max_step(const Positions& x, const Positions& dx) const override;

  /// Σ of −∇B on all particles from half-space `plane` (in the model's collider order) [N].
  xpbd::Vec3 force_from_plane(const Positions& x, int plane) const;

 private:
  struct Plane {
    const xpbd::Collider* collider;
    xpbd::Vec3 normal;
    double offset;
  };
  double gap(int e, const LocalVector& x) const;

  BarrierSettings settings_;
  std::vector<EmbeddedSphere> spheres_;
  std::vector<Plane> planes_;
  std::vector<std::array<int, 2>> elements_;  ///< sphere, plane
};

}  // namespace rice::fem
