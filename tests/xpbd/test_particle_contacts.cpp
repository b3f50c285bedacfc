// Contacts held in each particle's step under vertex block descent (particle_contacts.hpp):
// the terms' derivatives by finite differences, the multiplier step's fixed point, and a soft
// grain resting on a plane at one substep per frame with the plane carrying its weight.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/particle_contacts.hpp"
#include "xpbd/solver.hpp"

namespace rice::xpbd {
namespace {

using namespace testing;

/// Two spheres' corners (particles 0–3 and 4–7) with weights summing to ±1, overlapping.
ParticleContacts overlapping_pair(const Positions& x, double force) {
  ParticleContact c;
  c.size = 8;
  c.particles = {0, 1, 2, 3, 4, 5, 6, 7};
  c.weights = {0.1, 0.2, 0.3, 0.4, -0.25, -0.25, -0.3, -0.2};
  c.normal = Vec3(0.3, -0.2, 0.9).normalized();
  c.stiffness = 500.0;
  c.force = force;
  c.offset = c.value(x) + c.offset + 1e-4;  // C = −1e-4: overlapping
  ParticleContacts contacts;
  contacts.add(c);
  contacts.index(8);
  return contacts;
}

TEST(ParticleContacts, TermsMatchFiniteDifferencesOfTheirEnergy) {
  Positions x = Positions::Random(8, 3) * 1e-3;
  for (const double force : {0.0, 0.02}) {
    const ParticleContacts contacts = overlapping_pair(x, force);
    for (int i = 0; i < 8; ++i) {
      Vec3 gradient = Vec3::Zero();
      Mat3 hessian = Mat3::Zero();
      contacts.add_particle_terms(x, i, gradient, hessian);
      const double eps = 1e-9;
      for (int d = 0; d < 3; ++d) {
        const Vec3 step = eps * Vec3::Unit(d);
        const double fd = (contacts.particle_energy(x, i, step) - contacts.particle_energy(x, i, -step)) / (2 * eps);
        EXPECT_NEAR(gradient[d], fd, 1e-6 * gradient.norm() + 1e-12) << "particle " << i << ", force " << force;
        Vec3 g_plus = Vec3::Zero(), g_minus = Vec3::Zero();
        Mat3 unused = Mat3::Zero();
        Positions moved = x;
        moved.row(i) += step.transpose();
        contacts.add_particle_terms(moved, i, g_plus, unused);
        moved.row(i) -= 2 * step.transpose();
        contacts.add_particle_terms(moved, i, g_minus, unused);
        const Vec3 column = (g_plus - g_minus) / (2 * eps);
        EXPECT_LT((hessian.col(d) - column).norm(), 1e-6 * hessian.norm()) << "particle " << i;
      }
    }
  }
}

TEST(ParticleContacts, TheForceStepStopsWhereTheContactTouchesOrParts) {
  // λ ← max(0, λ − k C): an overlap raises λ by k|C|; a gap lowers it, never below 0; C = 0
  // leaves it (the fixed point with the contact touching).
  Positions x = Positions::Random(8, 3) * 1e-3;
  ParticleContacts contacts = overlapping_pair(x, 0.02);
  contacts.update_forces(x);
  EXPECT_NEAR(contacts.contacts()[0].force, 0.02 + 500.0 * 1e-4, 1e-12);
  contacts.contacts()[0].offset -= 1e-4;  // touching
  contacts.update_forces(x);
  EXPECT_NEAR(contacts.contacts()[0].force, 0.07, 1e-12);
  contacts.contacts()[0].offset -= 1.0;  // far apart
  contacts.update_forces(x);
  EXPECT_EQ(contacts.contacts()[0].force, 0.0);
}

TEST(ParticleContacts, ASoftGrainRestsOnAPlaneAtOneStepPerFrame) {
  // Vertex block descent at h = 1/60 s, 20 sweeps: the plane is a half-space collider met by
  // the grain's spheres. After a second on it the grain's spheres stay within 5 µm of the
  // plane's surface (0.25% of its thickness; the multiplier steps leave µm overlaps that come
  // and go) and the plane carries its weight to 1% (measured: 0.1%).
  Model model;
  const int grain = add_grain(model, BodyKind::kSoft, Vec3(0.0, 0.0, 1e-4));
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.0, 0.0));
  Solver solver(model, {.time_step = 1.0 / 60.0, .substeps = 1, .iterations = 20, .method = Method::kVbd,
                        .execution = Execution::kSerial});
  for (int k = 0; k < 60; ++k) solver.step();
  const double weight = kGrainDensity * kGrainLength * kGrainWidth * kGrainThickness * 9.81;
  double load = 0.0;
  for (int k = 0; k < 60; ++k) {
    solver.step();
    EXPECT_LT(std::abs(lowest_point(model, grain)), 5e-6) << "step " << k;
    load -= solver.contacts()->statistics().collider_forces.at(0).z() / 60.0;
  }
  EXPECT_NEAR(load, weight, 0.01 * weight);
}

}  // namespace
}  // namespace rice::xpbd
