// Rigid bodies (rigid_body.hpp): mass properties against the analytic box, the generalised
// inverse mass against finite differences, momentum of paired impulses, torque-free spin.
#include <gtest/gtest.h>

#include <cmath>

#include "xpbd/rigid_body.hpp"
#include "xpbd/tet_mesh.hpp"

namespace rice::xpbd {
namespace {

TEST(RigidBody, MassPropertiesOfABoxMatchTheClosedForm) {
  const Vec3 size(0.3, 0.2, 0.1);
  TetMesh mesh = make_box_tet_mesh(size, 3, 2, 2);
  mesh.V.rowwise() += Eigen::RowVector3d(1.0, -2.0, 0.5);
  const double rho = 700.0;
  const MassProperties m = mass_properties(mesh.V, mesh.T, rho);
  const double mass = rho * size.prod();
  EXPECT_NEAR(m.mass, mass, 1e-12 * mass);
  EXPECT_LT((m.centre - Vec3(1.15, -1.9, 0.55)).norm(), 1e-12);
  const Vec3 s2 = size.cwiseProduct(size);
  const Mat3 expected = (mass / 12.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y())).asDiagonal();
  EXPECT_LT((m.inertia - expected).norm(), 1e-12 * expected.norm());
}

RigidBody tilted_box() {
  const TetMesh mesh = make_box_tet_mesh(Vec3(0.3, 0.2, 0.1), 3, 2, 2);
  RigidBody body = make_rigid_body(mesh.V, mesh.T, 500.0);
  body.set_orientation(Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized())) * body.q());
  return body;
}

TEST(RigidBody, GeneralizedInverseMassIsTheDisplacementPerImpulse) {
  // MMCJK20 eq. 2: a positional impulse p = ε n at a point moves that material point by
  // w ε along n, to first order in ε.
  const RigidBody body = tilted_box();
  const Vec3 point = body.x + Vec3(0.12, -0.07, 0.04);
  const Vec3 local = body.to_local(point);
  for (const Vec3& n : {Vec3(Vec3::UnitX()), Vec3(0.3, -0.8, 0.52).normalized()}) {
    const double w = generalized_inverse_mass(body, point - body.x, n);
    const double epsilon = 1e-7;
    RigidBody pushed = body;
    apply_positional_impulse(pushed, point - body.x, epsilon * n);
    const double moved = n.dot(pushed.world_point(local) - point) / epsilon;
    EXPECT_NEAR(moved, w, 1e-5 * w);
  }
}

TEST(RigidBody, OppositeImpulsesConserveMomentum) {
  RigidBody a = tilted_box(), b = tilted_box();
  b.x += Vec3(0.25, 0.05, 0.0);
  a.remember_pose();
  b.remember_pose();
  const Vec3 contact = 0.5 * (a.x + b.x) + Vec3(0.0, 0.02, 0.01);
  const Vec3 p = 1e-6 * Vec3(1.0, 0.3, -0.2);
  apply_positional_impulse(a, contact - a.x, -p);
  apply_positional_impulse(b, contact - b.x, p);
  const double h = 1e-3;
  update_velocities(a, h);
  update_velocities(b, h);
  const auto momentum = [](const RigidBody& r) -> Vec3 { return r.v / r.inverse_mass; };
  const auto angular = [&](const RigidBody& r) -> Vec3 { return r.x.cross(momentum(r)) + r.angular_momentum(); };
  EXPECT_LT((momentum(a) + momentum(b)).norm(), 1e-12 * momentum(a).norm());
  // Exact for the linearised rotation; the normalised quaternion update is second order.
  EXPECT_LT((angular(a) + angular(b)).norm(), 1e-4 * angular(a).norm());
}

/// |L(1 s) − L(0)| / |L(0)| of a torque-free spin about the largest-inertia axis, perturbed.
double angular_momentum_drift(double h) {
  RigidBody body = tilted_box();
  body.omega = body.q() * Vec3(0.2, 0.1, 10.0);
  const auto angular = [&] { return body.angular_momentum(); };
  const Vec3 L0 = angular();
  for (int k = 0; k < static_cast<int>(std::lround(1.0 / h)); ++k) {
    integrate(body, Vec3::Zero(), h);
    update_velocities(body, h);
  }
  return (angular() - L0).norm() / L0.norm();
}

TEST(RigidBody, TorqueFreeSpinKeepsItsAngularMomentumToFirstOrder) {
  // The gyroscopic term is integrated explicitly (Algorithm 2), so L drifts by O(h).
  const double coarse = angular_momentum_drift(1e-3), fine = angular_momentum_drift(5e-4);
  EXPECT_LT(coarse, 2e-2);
  EXPECT_NEAR(coarse / fine, 2.0, 0.3);
}

}  // namespace
}  // namespace rice::xpbd
