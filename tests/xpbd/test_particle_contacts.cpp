// Contacts, friction and bonds held in each particle's step under vertex block descent
// (particle_contacts.hpp): the terms' derivatives by finite differences, the multiplier step's
// fixed point, and a soft grain resting on a plane at one substep per frame with the plane
// carrying its weight.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/particle_contacts.hpp"
#include "xpbd/solver.hpp"

namespace rice::xpbd {
namespace {

using namespace test_support;

/// Two spheres' corners (particles 0–3 and 4–7) with weights summing to ±1.
LinearPoint pair_point() {
  LinearPoint p;
  p.size = 8;
  p.particles = {0, 1, 2, 3, 4, 5, 6, 7};
  p.weights = {0.1, 0.2, 0.3, 0.4, -0.25, -0.25, -0.3, -0.2};
  return p;
}

/// The pair overlapping by 0.1 mm; with `friction` μ, a slip of (12, −5, ·) µm since the
/// substep's start and the bound m = μ f_n of its normal force.
ParticleContacts overlapping_pair(const Positions& x, double force, double friction = 0.0) {
  ParticleContact c;
  c.point = pair_point();
  c.normal = Vec3(0.3, -0.2, 0.9).normalized();
  c.stiffness = 500.0;
  c.force = force;
  c.offset = c.value(x) + 1e-4;  // C = −1e-4: overlapping
  c.friction = friction;
  c.slip_origin = c.point.at(x) - Vec3(1.2e-5, -5e-6, 0.0);
  c.friction_force = Vec3(-1e-3, 2e-3, 0.0);
  c.friction_force -= c.normal.dot(c.friction_force) * c.normal;
  ParticleContacts contacts;
  contacts.add(c);
  contacts.index(8);
  contacts.set_friction_bounds(x);
  return contacts;
}

/// A bond stretched 30 µm past its length, k* = 1e4 N/m.
ParticleContacts stretched_bond(const Positions& x) {
  ParticleBond b;
  b.point = pair_point();
  b.offset = Vec3(2e-4, -1e-4, 5e-4);
  b.length = (b.point.at(x) + b.offset).norm() - 3e-5;
  b.stiffness = 1e4;
  ParticleContacts contacts;
  contacts.add(b);
  contacts.index(8);
  return contacts;
}

/// Every particle's gradient and Hessian against central differences of its energy and gradient.
void expect_terms_match_finite_differences(const ParticleContacts& contacts, const Positions& x,
                                           const std::string& what) {
  for (int i = 0; i < 8; ++i) {
    Vec3 gradient = Vec3::Zero();
    Mat3 hessian = Mat3::Zero();
    contacts.add_particle_terms(x, i, gradient, hessian);
    ASSERT_GT(gradient.norm(), 0.0) << what;
    const double eps = 1e-9;
    for (int d = 0; d < 3; ++d) {
      const Vec3 step = eps * Vec3::Unit(d);
      const double fd = (contacts.particle_energy(x, i, step) - contacts.particle_energy(x, i, -step)) / (2 * eps);
      EXPECT_NEAR(gradient[d], fd, 1e-6 * gradient.norm() + 1e-12) << what << ", particle " << i;
      Vec3 g_plus = Vec3::Zero(), g_minus = Vec3::Zero();
      Mat3 unused = Mat3::Zero();
      Positions moved = x;
      moved.row(i) += step.transpose();
      contacts.add_particle_terms(moved, i, g_plus, unused);
      moved.row(i) -= 2 * step.transpose();
      contacts.add_particle_terms(moved, i, g_minus, unused);
      const Vec3 column = (g_plus - g_minus) / (2 * eps);
      EXPECT_LT((hessian.col(d) - column).norm(), 1e-6 * hessian.norm()) << what << ", particle " << i;
    }
  }
}

TEST(ParticleContacts, TermsMatchFiniteDifferencesOfTheirEnergy) {
  const Positions x = Positions::Random(8, 3) * 1e-3;
  for (const double force : {0.0, 0.02})
    expect_terms_match_finite_differences(overlapping_pair(x, force), x, "contact, force " + std::to_string(force));
  // Friction inside its cone (μ = 20: |u| = 7 mN under m = 0.5 N) has the Hessian k P exactly.
  expect_terms_match_finite_differences(overlapping_pair(x, 0.02, 20.0), x, "sticking friction");
  expect_terms_match_finite_differences(stretched_bond(x), x, "bond");
}

TEST(ParticleContacts, SlidingFrictionIsTheCappedForceWithTheHuberHessian) {
  // μ = 0.1: m = 7 mN against |u| ≈ 8 mN, on the cone: the gradient is −a_j f_t with |f_t| = m.
  const Positions x = Positions::Random(8, 3) * 1e-3;
  const ParticleContacts contacts = overlapping_pair(x, 0.02, 0.1);
  const ParticleContact& c = contacts.contacts()[0];
  ASSERT_GT(c.friction_trial(c.point.at(x)).norm(), c.friction_bound);
  expect_terms_match_finite_differences(contacts, x, "sliding friction");
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

SolverSettings vbd_settings(double time_step, int iterations) {
  return {.time_step = time_step, .substeps = 1, .iterations = iterations, .method = Method::kVbd,
          .execution = Execution::kSerial};
}

/// A soft grain set down on a plane collider, then gravity tilted by θ (tan θ = `tan_theta`),
/// by vertex block descent at h = 1/120 s and 20 sweeps (10 slid 8.5% slow): how far it slid along the slope in
/// `seconds`, and its acceleration over the second half. (Tilted from the start, the landing
/// set it sliding, and μ_k < tan θ < μ_s kept it going, as it would a real grain.)
double soft_slide_after(double tan_theta, double mu_s, double mu_k, double seconds, double* acceleration) {
  Model model;
  const int grain = add_grain(model, BodyKind::kSoft, Vec3::Zero());
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, mu_s, mu_k));
  const double fps = 120.0;
  Solver solver(model, vbd_settings(1.0 / fps, 20));
  for (int k = 0; k < 60; ++k) solver.step();
  const double theta = std::atan(tan_theta);
  model.gravity = 9.81 * Vec3(std::sin(theta), 0.0, -std::cos(theta));
  const double x0 = body_centre(model, grain).x();
  const int steps = static_cast<int>(std::lround(seconds * fps));
  double v_half = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double x_before = body_centre(model, grain).x();
    solver.step();
    const double v = (body_centre(model, grain).x() - x_before) * fps;
    if (k == steps / 2) v_half = v;
    if (k == steps - 1 && acceleration) *acceleration = (v - v_half) / ((steps - 1 - steps / 2) / fps);
  }
  return body_centre(model, grain).x() - x0;
}

TEST(ParticleStepFriction, ASoftGrainSticksBelowItsAngle) {
  const double mu_s = 0.5, mu_k = 0.4;
  EXPECT_LT(std::abs(soft_slide_after(0.9 * mu_s, mu_s, mu_k, 1.0, nullptr)), 1e-6);
}

TEST(ParticleStepFriction, ASoftGrainSlidesAboveItsAngleWithTheDynamicAcceleration) {
  const double mu_s = 0.5, mu_k = 0.4, tan_theta = 1.1 * mu_s;
  double acceleration = 0.0;
  EXPECT_GT(soft_slide_after(tan_theta, mu_s, mu_k, 0.6, &acceleration), 1e-3);
  const double theta = std::atan(tan_theta);
  const double expected = 9.81 * (std::sin(theta) - mu_k * std::cos(theta));
  EXPECT_NEAR(acceleration, expected, 0.05 * expected);
  RecordProperty("acceleration_over_expected", std::to_string(acceleration / expected));
}

/// One grain pinned, the other bonded under it (8 µm gap, no gravity) and pulled down by a
/// force that ramps from 0 to twice the pair's strength over 2 s, a step at a time: the pull
/// over the strength at which the pair's bonds break. The ramp is slow, so the bonds carry the
/// whole pull, and a solver that holds them right breaks them at 1.
double breaking_pull_over_strength(const SolverSettings& settings) {
  Model model;
  model.gravity.setZero();
  model.contact.cohesion = true;
  const int top = add_grain(model, BodyKind::kSoft, Vec3(0.0, 0.0, kGrainThickness + 8e-6));
  const int bottom = add_grain(model, BodyKind::kSoft, Vec3::Zero());
  const double strength = 1e-3;  // N, about two of the grain's weights
  for (Body& body : model.bodies) body.bond_strength = strength;
  const Body& pinned = model.bodies[top];
  model.particles.w.segment(pinned.first_particle, pinned.particle_count).setZero();
  const Body& pulled = model.bodies[bottom];
  model.external_forces = Positions::Zero(model.particles.size(), 3);
  double mass = 0.0;
  for (int i = pulled.first_particle; i < pulled.first_particle + pulled.particle_count; ++i)
    mass += 1.0 / model.particles.w[i];
  const double ramp = 2.0 * strength / 2.0, fps = 1.0 / settings.time_step;  // N/s, steps a second
  Solver solver(model, settings);
  for (int k = 0; k < 5; ++k) solver.step();  // the bonds form
  EXPECT_GE(solver.contacts()->statistics().bonds, 3);
  double pull = 0.0;
  for (int k = 0; k < 2 * fps && solver.contacts()->statistics().bonds_broken == 0; ++k) {
    pull = ramp * k / fps;
    for (int i = pulled.first_particle; i < pulled.first_particle + pulled.particle_count; ++i)
      model.external_forces.row(i) = Eigen::RowVector3d(0.0, 0.0, -pull / (mass * model.particles.w[i]));
    solver.step();
  }
  EXPECT_EQ(solver.contacts()->statistics().bonds_broken, 1);
  return pull / strength;
}

TEST(ParticleStepBonds, TwoBondedSoftGrainsPulledApartBreakAtTheirStrength) {
  // (With the bonds' springs at 1/α = 1e4 N/m, the grain rang on them, their force swung ±50%
  // about the pull, and the pair broke at 29% of its strength.)
  const double ratio = breaking_pull_over_strength(vbd_settings(1.0 / 300.0, 10));
  EXPECT_NEAR(ratio, 1.0, 0.05);
  RecordProperty("breaking_pull_over_strength", std::to_string(ratio));
}

TEST(XpbdBonds, TwoBondedSoftGrainsPulledApartBreakAtTheirStrengthAtEverySubstep) {
  // 16, 48 and 96 substeps of 1/300 s: 160, 480 and 960 a 30 fps frame, the scenes' range.
  for (const int substeps : {16, 48, 96}) {
    const SolverSettings settings{.time_step = 1.0 / 300.0, .substeps = substeps, .iterations = 1,
                                  .method = Method::kXpbd, .execution = Execution::kSerial};
    const double ratio = breaking_pull_over_strength(settings);
    EXPECT_NEAR(ratio, 1.0, 0.05) << substeps << " substeps";
    RecordProperty("breaking_pull_over_strength_" + std::to_string(substeps), std::to_string(ratio));
  }
}

}  // namespace
}  // namespace rice::xpbd
