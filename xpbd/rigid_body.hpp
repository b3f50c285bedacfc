// Rigid bodies for XPBD (Müller, Macklin, Chentanez, Jeschke & Kim 2020, "Detailed Rigid Body
// Simulation with Extended Position Based Dynamics", MMCJK20 below): the pose (centre of mass
// x, orientation q), the velocities (v, ω), mass and principal inertia, the substep
// integration and velocity update of Algorithm 2, and the positional impulse of §3.3 through
// which contacts move a body. A rigid grain has six degrees of freedom and no tet solves.
#pragma once

#include <Eigen/Geometry>

#include "xpbd/types.hpp"

namespace rice::xpbd {

using Quat = Eigen::Quaterniond;

/// The orientation is kept with its rotation matrix (R and the previous pose's Rₚ), which
/// every point transform uses: quaternion–vector products took 38% of a settling pile's time.
/// Change it only through set_orientation and remember_pose, which keep the two in step.
struct RigidBody {
  Vec3 x = Vec3::Zero();      ///< centre of mass [m]
  Vec3 v = Vec3::Zero();      ///< [m/s]
  Vec3 omega = Vec3::Zero();  ///< angular velocity, world frame [rad/s]
  double inverse_mass = 0.0;  ///< 1/m [1/kg]; 0 makes the body immovable
  Vec3 inverse_inertia = Vec3::Zero();  ///< 1/I of the principal moments, body frame [1/(kg m²)]
  Vec3 x_previous = Vec3::Zero();      ///< centre at the start of the substep

  const Quat& q() const { return q_; }  ///< orientation: world = x + q · local
  const Quat& q_previous() const { return q_previous_; }
  const Mat3& R() const { return R_; }
  /// Sets q (normalised) and R.
  void set_orientation(const Quat& q) {
    q_ = q.normalized();
    R_ = q_.toRotationMatrix();
  }
  /// Stores the pose as the substep's start (x_previous, q_previous).
  void remember_pose() {
    x_previous = x;
    q_previous_ = q_;
    R_previous_ = R_;
  }

  Vec3 world_point(const Vec3& local) const { return x + R_ * local; }
  Vec3 previous_world_point(const Vec3& local) const { return x_previous + R_previous_ * local; }
  Vec3 to_local(const Vec3& world) const { return R_.transpose() * (world - x); }
  /// Body-frame coordinates of a world point at the substep's start.
  Vec3 to_previous_local(const Vec3& world) const { return R_previous_.transpose() * (world - x_previous); }
  /// I⁻¹ u in the world frame: R diag(1/I) Rᵀ u.
  Vec3 apply_inverse_inertia(const Vec3& u) const {
    return R_ * inverse_inertia.cwiseProduct(R_.transpose() * u);
  }
  /// I ω in the world frame (angular momentum about the centre).
  Vec3 angular_momentum() const { return R_ * (R_.transpose() * omega).cwiseQuotient(inverse_inertia); }

 private:
  Quat q_ = Quat::Identity(), q_previous_ = Quat::Identity();
  Mat3 R_ = Mat3::Identity(), R_previous_ = Mat3::Identity();
};

/// Mass, centre of mass and inertia tensor about the centre (mesh axes) of a tet mesh of
/// density ρ, from the exact second moment of each tetrahedron:
///   ∫_T x xᵀ dV = V/20 (Σᵢ xᵢxᵢᵀ + s sᵀ), s = Σᵢ xᵢ,   I = tr(C) 1 − C.
struct MassProperties {
  double mass = 0.0;
  Vec3 centre = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
};
MassProperties mass_properties(const Positions& V, const Tets& T, double density);

/// A body at rest where the mesh lies: x at its centre of mass, q the rotation from the
/// principal frame (body frame) to the mesh frame. Throws for a mesh with no positive volume.
RigidBody make_rigid_body(const Positions& V, const Tets& T, double density);

/// Algorithm 2, first loop: remembers the pose, then v += h g, x += h v,
/// ω += h I⁻¹(−ω × Iω) (torque-free gyroscopic term) and q += h/2 [ω, 0] q, normalised.
void integrate(RigidBody& body, const Vec3& gravity, double h);

/// Algorithm 2, velocity update: v = (x − xₚ)/h, ω = 2 vec(q qₚ⁻¹)/h (sign of the real part).
void update_velocities(RigidBody& body, double h);

/// MMCJK20 eq. 2–3: w = 1/m + (r × n)ᵀ I⁻¹ (r × n), the inverse mass the body shows to a
/// positional correction along the unit vector n applied at r = point − x.
double generalized_inverse_mass(const RigidBody& body, const Vec3& r, const Vec3& n);

/// MMCJK20 eq. 6–9: a positional impulse p at r = point − x moves x += p/m and turns
/// q += ½ [I⁻¹(r × p), 0] q, normalised.
void apply_positional_impulse(RigidBody& body, const Vec3& r, const Vec3& p);

}  // namespace rice::xpbd
