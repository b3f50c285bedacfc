// Rigid body integration and positional impulses; see rigid_body.hpp.
#include "xpbd/rigid_body.hpp"

#include <stdexcept>
#include <string>

#include "xpbd/tet_mesh.hpp"

namespace rice::xpbd {
namespace {

/// q += ½ [θ, 0] q, normalised: the first-order rotation of q by the small angle vector θ.
void rotate(RigidBody& body, const Vec3& theta) {
  const Quat dq(0.0, theta.x(), theta.y(), theta.z());
  Quat q = body.q();
  q.coeffs() += 0.5 * (dq * q).coeffs();
  body.set_orientation(q);
}

}  // namespace

MassProperties mass_properties(const Positions& V, const Tets& T, double density) {
  if (!(density > 0.0)) throw std::invalid_argument("mass_properties: density must be > 0");
  const Eigen::VectorXd volumes = tet_volumes(V, T);
  double volume = 0.0;
  Vec3 first_moment = Vec3::Zero();
  Mat3 second_moment = Mat3::Zero();  // ∫ x xᵀ dV about the origin
  for (int t = 0; t < T.rows(); ++t) {
    Vec3 s = Vec3::Zero();
    Mat3 sum_outer = Mat3::Zero();
    for (int k = 0; k < 4; ++k) {
      const Vec3 xk = V.row(T(t, k)).transpose();
      s += xk;
      sum_outer += xk * xk.transpose();
    }
    volume += volumes[t];
    first_moment += volumes[t] * s / 4.0;
    second_moment += volumes[t] / 20.0 * (sum_outer + s * s.transpose());
  }
  if (!(volume > 0.0))
    throw std::invalid_argument("mass_properties: the mesh has volume " + std::to_string(volume));
  MassProperties m;
  m.mass = density * volume;
  m.centre = first_moment / volume;
  const Mat3 C = density * (second_moment - volume * m.centre * m.centre.transpose());
  m.inertia = C.trace() * Mat3::Identity() - C;
  return m;
}

RigidBody make_rigid_body(const Positions& V, const Tets& T, double density) {
  const MassProperties m = mass_properties(V, T, density);
  const Eigen::SelfAdjointEigenSolver<Mat3> principal(m.inertia);
  Mat3 R = principal.eigenvectors();
  if (R.determinant() < 0.0) R.col(2) = -R.col(2);
  RigidBody body;
  body.x = m.centre;
  body.set_orientation(Quat(R));
  body.remember_pose();
  body.inverse_mass = 1.0 / m.mass;
  body.inverse_inertia = principal.eigenvalues().cwiseInverse();
  return body;
}

void integrate(RigidBody& body, const Vec3& gravity, double h) {
  body.remember_pose();
  if (body.inverse_mass == 0.0) return;
  body.v += h * gravity;
  body.x += h * body.v;
  body.omega += h * body.apply_inverse_inertia(-body.omega.cross(body.angular_momentum()));
  rotate(body, h * body.omega);
}

void update_velocities(RigidBody& body, double h) {
  if (body.inverse_mass == 0.0) return;
  body.v = (body.x - body.x_previous) / h;
  const Quat dq = body.q() * body.q_previous().conjugate();
  body.omega = 2.0 / h * dq.vec();
  if (dq.w() < 0.0) body.omega = -body.omega;
}

double generalized_inverse_mass(const RigidBody& body, const Vec3& r, const Vec3& n) {
  if (body.inverse_mass == 0.0) return 0.0;
  const Vec3 rn = r.cross(n);
  return body.inverse_mass + rn.dot(body.apply_inverse_inertia(rn));
}

void apply_positional_impulse(RigidBody& body, const Vec3& r, const Vec3& p) {
  if (body.inverse_mass == 0.0) return;
  body.x += body.inverse_mass * p;
  rotate(body, body.apply_inverse_inertia(r.cross(p)));
}

}  // namespace rice::xpbd
