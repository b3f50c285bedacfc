// Model energies; see energy.hpp.
#include "xpbd/energy.hpp"

#include "xpbd/distance_constraint.hpp"
#include "xpbd/tet_constraint_pair.hpp"
#include "xpbd/tet_volume_constraint.hpp"

namespace rice::xpbd {
namespace {

Vec12 gather(const Positions& x, const std::array<int, 4>& ids) {
  return stack(x.row(ids[0]).transpose(), x.row(ids[1]).transpose(), x.row(ids[2]).transpose(),
               x.row(ids[3]).transpose());
}

double half_c2_over_alpha(double C, double alpha) { return alpha > 0.0 ? 0.5 * C * C / alpha : 0.0; }

}  // namespace

double kinetic_energy(const Particles& particles) {
  double energy = 0.0;
  for (int i = 0; i < particles.size(); ++i)
    if (particles.w[i] > 0.0) energy += 0.5 * particles.v.row(i).squaredNorm() / particles.w[i];
  return energy;
}

double kinetic_energy(const Model& model) {
  double energy = kinetic_energy(model.particles);
  for (const RigidBody& b : model.rigid_bodies) {
    if (b.inverse_mass == 0.0) continue;
    energy += 0.5 * b.v.squaredNorm() / b.inverse_mass + 0.5 * b.omega.dot(b.angular_momentum());
  }
  return energy;
}

double gravitational_energy(const Model& model) {
  const Particles& p = model.particles;
  double energy = 0.0;
  for (int i = 0; i < p.size(); ++i)
    if (p.w[i] > 0.0) energy -= p.x.row(i).dot(model.gravity.transpose()) / p.w[i];
  for (const RigidBody& b : model.rigid_bodies)
    if (b.inverse_mass > 0.0) energy -= b.x.dot(model.gravity) / b.inverse_mass;
  return energy;
}

double elastic_energy(const Model& model) {
  const Positions& x = model.particles.x;
  double energy = 0.0;
  for (const DistanceConstraint& c : model.distances)
    energy += half_c2_over_alpha(distance_constraint_value(x.row(c.particles[0]).transpose(),
                                                           x.row(c.particles[1]).transpose(),
                                                           c.rest_length),
                                 c.compliance);
  for (const TetVolumeConstraint& c : model.volumes)
    energy += half_c2_over_alpha(tet_volume_constraint_value(gather(x, c.particles), c.rest_volume),
                                 c.compliance);
  for (const NeoHookeanTet& t : model.neo_hookean) {
    const Vec2 C = tet_constraint_pair(t, deformation_gradient(gather(x, t.particles), t.Dm_inv)).C;
    energy += half_c2_over_alpha(C[0], t.compliance_deviatoric()) +
              half_c2_over_alpha(C[1], t.compliance_hydrostatic()) - t.rest_energy();
  }
  for (const Attachment& a : model.attachments)
    if (a.compliance > 0.0)
      energy += 0.5 * (x.row(a.particle).transpose() - a.target).squaredNorm() / a.compliance;
  return energy;
}

Positions elastic_energy_gradient(const Model& model) {
  const Positions& x = model.particles.x;
  Positions gradient = Positions::Zero(x.rows(), 3);
  const auto scatter = [&](const std::array<int, 4>& ids, const Vec12& g) {
    for (int k = 0; k < 4; ++k) gradient.row(ids[k]) += g.segment<3>(3 * k).transpose();
  };
  // ∇(½ C²/α) = (C/α) ∇C
  for (const DistanceConstraint& c : model.distances) {
    if (!(c.compliance > 0.0)) continue;
    const Vec3 xi = x.row(c.particles[0]).transpose(), xj = x.row(c.particles[1]).transpose();
    const Vec6 g = distance_constraint_value(xi, xj, c.rest_length) / c.compliance *
                   distance_constraint_gradient(xi, xj);
    gradient.row(c.particles[0]) += g.head<3>().transpose();
    gradient.row(c.particles[1]) += g.tail<3>().transpose();
  }
  for (const TetVolumeConstraint& c : model.volumes) {
    if (!(c.compliance > 0.0)) continue;
    const Vec12 xs = gather(x, c.particles);
    scatter(c.particles, tet_volume_constraint_value(xs, c.rest_volume) / c.compliance *
                             tet_volume_constraint_gradient(xs));
  }
  for (const NeoHookeanTet& t : model.neo_hookean) {
    const TetConstraintPair p = tet_constraint_pair(t, deformation_gradient(gather(x, t.particles), t.Dm_inv));
    const Mat3 dUdF = p.C[0] / t.compliance_deviatoric() * p.dD + p.C[1] / t.compliance_hydrostatic() * p.dH;
    scatter(t.particles, gradient_from_dF(dUdF, t.Dm_inv));
  }
  for (const Attachment& a : model.attachments)
    if (a.compliance > 0.0)
      gradient.row(a.particle) += (x.row(a.particle) - a.target.transpose()) / a.compliance;
  return gradient;
}

double max_speed(const Particles& particles) {
  return particles.v.rows() ? particles.v.rowwise().norm().maxCoeff() : 0.0;
}

}  // namespace rice::xpbd
