// Contact between grains and against colliders (contact_solver.hpp), on grain-sized bodies
// (grain_fixtures.hpp), each test for a rigid and a soft grain: resting without drift,
// friction against the analytic sliding threshold and acceleration, momentum and energy in a
// free-space collision, and no tunnelling at 5 m/s with the frame-rate step of the scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/broad_phase.hpp"
#include "xpbd/cohesion_bonds.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/distance_grid.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/penetration.hpp"
#include "xpbd/sleeping.hpp"
#include "xpbd/solver.hpp"
#include "xpbd/state_archive.hpp"

namespace rice::xpbd {
namespace {

using namespace test_support;

class GrainContact : public ::testing::TestWithParam<BodyKind> {};

std::string kind_name(const ::testing::TestParamInfo<BodyKind>& info) {
  return info.param == BodyKind::kRigid ? "Rigid" : "Soft";
}

/// Rigid grains take `substeps`; soft ones at least enough to keep each substep under the
/// Neo-Hookean pair's stability limit (README "Known limits": about 2e-4 s for these tets).
SolverSettings scene_settings(BodyKind kind, double time_step, int substeps) {
  SolverSettings s;
  s.time_step = time_step;
  s.substeps = kind == BodyKind::kRigid ? substeps : std::max(substeps, static_cast<int>(std::ceil(time_step / 1.5e-4)));
  s.iterations = 1;
  s.execution = Execution::kSerial;
  return s;
}

TEST_P(GrainContact, RestsOnAPlaneWithoutDrift) {
  // Issue: 1000 steps at rest on a plane, drift < 1e-6 m, penetration < 1% of the thickness.
  Model model;
  const int grain = add_grain(model, GetParam(), Vec3::Zero());
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  Solver solver(model, scene_settings(GetParam(), 1.0 / 300.0, 10));
  for (int k = 0; k < 50; ++k) solver.step();  // settle the first contact
  const Vec3 start = body_centre(model, grain);
  double deepest = 0.0;
  for (int k = 0; k < 1000; ++k) {
    solver.step();
    deepest = std::max(deepest, -lowest_point(model, grain));
  }
  EXPECT_LT((body_centre(model, grain) - start).norm(), 1e-6);
  EXPECT_LT(deepest, 0.01 * kGrainThickness);
  EXPECT_LT(solver.contacts()->statistics().max_penetration, 0.01 * kGrainThickness);
  // At rest the plane carries the grain's weight, straight down.
  const double weight = kGrainDensity * kGrainLength * kGrainWidth * kGrainThickness * 9.81;
  ASSERT_EQ(solver.contacts()->statistics().collider_forces.size(), 1u);
  const Vec3 load = solver.contacts()->statistics().collider_forces[0];
  EXPECT_NEAR(load.z(), -weight, 0.01 * weight);
  EXPECT_LT(load.head<2>().norm(), 0.01 * weight);
}

TEST(ContactStates, APileKeepsTheStatesOfItsContactsOnly) {
  // 27 rigid grains, spinning at random, dropped as a block onto a plane: they tumble over one
  // another's spheres into a pile. The sphere pairs left behind carry nothing (no anchors, no
  // sliding, no impulse in the interval) and are dropped, so a pile at rest holds about one
  // state a contact. (They were kept while their body pair stayed in reach: 41 states a
  // grain against 3.2 contacts in a 3000-grain clump, all copied every substep.) Friction
  // high enough that no pair slides, since a sliding pair's states are kept.
  Model model;
  model.contact.static_friction = 5.0;
  model.contact.dynamic_friction = 4.0;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> spin(-40.0, 40.0);
  for (int i = 0; i < 27; ++i) {
    const int grain = add_grain(model, BodyKind::kRigid,
                                Vec3((i % 3) * 8e-3, (i / 3 % 3) * 4e-3, 1e-3 + (i / 9) * 3e-3));
    model.rigid_bodies[model.bodies[grain].rigid_body].omega = Vec3(spin(rng), spin(rng), spin(rng));
  }
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 5.0, 4.0));
  Solver solver(model, scene_settings(BodyKind::kRigid, 1.0 / 30.0, 80));
  for (int k = 0; k < 45; ++k) solver.step();
  const ContactStatistics& at_rest = solver.contacts()->statistics();
  ASSERT_GT(at_rest.contacts, 100);
  // Within 5%: a pair that parted in the last broad-phase interval still holds its sums.
  EXPECT_LE(at_rest.states, at_rest.contacts + at_rest.contacts / 20);
}

TEST_P(GrainContact, FallsAsleepOnAColliderAndStaysAsleep) {
  // A grain at rest on a collider sleeps after SleepSettings::steps quiet steps; being near
  // a collider at rest must not keep it awake (it did, until the broad phase only woke
  // sleeping bodies).
  Model model;
  const int grain = add_grain(model, GetParam(), Vec3(0.0, 0.0, 1e-4));
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  model.sleep.enabled = true;
  Solver solver(model, scene_settings(GetParam(), 1.0 / 30.0, 80));
  int steps = 0;
  for (; steps < 60 && !model.bodies[grain].asleep; ++steps) solver.step();
  EXPECT_TRUE(model.bodies[grain].asleep) << "awake after " << steps << " frames";
  const Vec3 asleep_at = body_centre(model, grain);
  const long substeps = solver.timings().substeps;
  for (int k = 0; k < 30; ++k) solver.step();
  EXPECT_TRUE(model.bodies[grain].asleep);
  EXPECT_EQ(body_centre(model, grain), asleep_at);
  // With nothing awake and nothing in reach, a step solves its first substep only.
  EXPECT_EQ(solver.timings().substeps - substeps, 30);
}

TEST(SleepingSoftGrains, ASleepingGrainKeepsItsPlaceAndRestsWhileItsNeighbourFalls) {
  // Substeps walk the awake particles only; what they did for every particle (xⁿ = x, v from
  // the substep's motion) mark_sleeping does once for the sleeping ones. A soft grain put to
  // sleep in flight (its velocity still 1 m/s) stays where it is with zero velocity, while an
  // awake one 5 cm away falls as free fall says.
  Model model;
  const int sleeping = add_grain(model, BodyKind::kSoft, Vec3(0.0, 0.0, 0.1));
  const int falling = add_grain(model, BodyKind::kSoft, Vec3(0.05, 0.0, 0.1));
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  model.sleep.enabled = true;
  const Body& body = model.bodies[sleeping];
  model.particles.v.middleRows(body.first_particle, body.particle_count).col(2).setConstant(1.0);
  model.bodies[sleeping].asleep = true;
  const Positions start = model.particles.x;
  const Vec3 falling_start = body_centre(model, falling);
  Solver solver(model, scene_settings(BodyKind::kSoft, 1.0 / 30.0, 40));
  solver.step();
  const auto rows = [&](const Positions& x) { return x.middleRows(body.first_particle, body.particle_count); };
  EXPECT_EQ(rows(model.particles.x), rows(start));
  EXPECT_EQ(rows(model.particles.v), Positions::Zero(body.particle_count, 3));
  const double t = 1.0 / 30.0, drop = 0.5 * 9.81 * t * t;  // 5.45 mm, from rest
  EXPECT_NEAR(falling_start.z() - body_centre(model, falling).z(), drop, 0.05 * drop);
}

TEST_P(GrainContact, ASolverResumedFromItsStateStepsLikeOneNeverStopped) {
  // A grain falls from 1 cm onto another asleep on a plane, 0.5 m from the origin. A solver
  // that loads the first one's state after a step goes on to the same bits. Before, a
  // sleeping body's box was not in the state and the loaded solver's was whatever its memory
  // held: here the falling grain passed through the sleeping one; in the spout scenes
  // resumed from their first checkpoint, parked grains woke.
  const auto make_model = [&] {
    Model model;
    const int sleeping = add_grain(model, GetParam(), Vec3(0.5, 0.0, 0.0));
    add_grain(model, GetParam(), Vec3(0.5, 0.0, kGrainThickness + 0.01));
    model.bodies[sleeping].asleep = true;
    model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
    model.sleep.enabled = true;
    return model;
  };
  const SolverSettings settings = scene_settings(GetParam(), 1.0 / 30.0, 40);
  Model whole = make_model(), resumed = make_model();
  Solver never_stopped(whole, settings);
  never_stopped.step();
  StateWriter state;
  never_stopped.save_state(state);
  Solver loaded(resumed, settings);
  StateReader in(state.bytes());
  loaded.load_state(in);
  for (int k = 0; k < 6; ++k) {
    never_stopped.step();
    loaded.step();
  }
  // They met: the sleeping grain was pushed aside.
  EXPECT_GT((body_centre(whole, 0) - body_centre(make_model(), 0)).head<2>().norm(), 1e-6);
  EXPECT_EQ(resumed.particles.x, whole.particles.x);
  ASSERT_EQ(resumed.rigid_bodies.size(), whole.rigid_bodies.size());
  for (size_t b = 0; b < whole.rigid_bodies.size(); ++b) {
    EXPECT_EQ(resumed.rigid_bodies[b].x, whole.rigid_bodies[b].x);
    EXPECT_EQ(resumed.rigid_bodies[b].q().coeffs(), whole.rigid_bodies[b].q().coeffs());
  }
}

/// Gravity tilted by θ about y is a plane tilted by θ: the grain sits on z = 0 and is pulled
/// along +x by g sin θ.
double slide_after(BodyKind kind, double tan_theta, double mu_s, double mu_k, double seconds, double* acceleration) {
  Model model;
  const int grain = add_grain(model, kind, Vec3::Zero());
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, mu_s, mu_k));
  const double theta = std::atan(tan_theta);
  model.gravity = 9.81 * Vec3(std::sin(theta), 0.0, -std::cos(theta));
  Solver solver(model, scene_settings(kind, 1.0 / 300.0, 10));
  const double x0 = body_centre(model, grain).x();
  const int steps = static_cast<int>(std::lround(seconds * 300.0));
  double v_half = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double x_before = body_centre(model, grain).x();
    solver.step();
    const double v = (body_centre(model, grain).x() - x_before) * 300.0;
    if (k == steps / 2) v_half = v;
    if (k == steps - 1 && acceleration) *acceleration = (v - v_half) / ((steps - 1 - steps / 2) / 300.0);
  }
  return body_centre(model, grain).x() - x0;
}

TEST_P(GrainContact, StaticFrictionHoldsBelowItsAngle) {
  const double mu_s = 0.5, mu_k = 0.4;
  EXPECT_LT(std::abs(slide_after(GetParam(), 0.9 * mu_s, mu_s, mu_k, 1.0, nullptr)), 1e-6);
}

TEST_P(GrainContact, SlidesAboveItsAngleWithTheDynamicAcceleration) {
  const double mu_s = 0.5, mu_k = 0.4, tan_theta = 1.1 * mu_s;
  double acceleration = 0.0;
  EXPECT_GT(slide_after(GetParam(), tan_theta, mu_s, mu_k, 0.6, &acceleration), 1e-3);
  const double theta = std::atan(tan_theta);
  const double expected = 9.81 * (std::sin(theta) - mu_k * std::cos(theta));
  EXPECT_NEAR(acceleration, expected, 0.05 * expected);
}

TEST_P(GrainContact, FreeCollisionConservesMomentumAndNeverGainsEnergy) {
  Model model;
  model.gravity.setZero();
  model.contact.static_friction = 0.5;
  model.contact.dynamic_friction = 0.4;
  const int a = add_grain(model, GetParam(), Vec3::Zero());
  add_grain(model, GetParam(), Vec3(kGrainLength + 1e-3, 1e-3, 0.8e-3));
  // Grain a flies at the other along x, spinning.
  if (GetParam() == BodyKind::kRigid) {
    model.rigid_bodies[0].v = Vec3(1.0, 0.05, 0.0);
    model.rigid_bodies[0].omega = Vec3(0.0, 0.0, 20.0);
  } else {
    const Body& body = model.bodies[a];
    model.particles.v.middleRows(body.first_particle, body.particle_count).rowwise() =
        Eigen::RowVector3d(1.0, 0.05, 0.0);
  }
  Solver solver(model, scene_settings(GetParam(), 1.0 / 300.0, 10));
  const Vec3 p0 = linear_momentum(model);
  double energy = kinetic_energy(model) + elastic_energy(model);
  int touching_steps = 0;
  for (int k = 0; k < 60; ++k) {
    solver.step();
    const double now = kinetic_energy(model) + elastic_energy(model);
    EXPECT_LE(now, energy * (1.0 + 1e-9)) << "step " << k;
    energy = now;
    if (solver.contacts()->statistics().contacts > 0) ++touching_steps;
  }
  EXPECT_GT(touching_steps, 0);
  EXPECT_LT((linear_momentum(model) - p0).norm(), 1e-9 * p0.norm());
}

TEST_P(GrainContact, DoesNotTunnelThroughAThinPlateAt5MetresPerSecond) {
  // A 1 mm plate and a grain falling onto it face first at 5 m/s: at 30 frames per second in
  // 20 substeps, the grain moves 8 mm, four times its thickness, per substep.
  Model model;
  model.gravity.setZero();
  Collider plate;
  plate.shape = ColliderShape::kBox;
  plate.half_extents = Vec3(0.02, 0.02, 0.5e-3);
  model.colliders.push_back(plate);
  const int grain = add_grain(model, GetParam(), Vec3(-3.5e-3, -1.5e-3, 0.03));
  if (GetParam() == BodyKind::kRigid)
    model.rigid_bodies[0].v = Vec3(0.0, 0.0, -5.0);
  else
    model.particles.v.col(2).setConstant(-5.0);
  Solver solver(model, scene_settings(GetParam(), 1.0 / 30.0, 20));
  for (int k = 0; k < 10; ++k) solver.step();
  EXPECT_GT(lowest_point(model, grain), 0.5e-3 - 0.05 * kGrainThickness);
}

TEST_P(GrainContact, DoesNotTunnelThroughAnotherGrainAt5MetresPerSecond) {
  Model model;
  model.gravity.setZero();
  const int target = add_grain(model, GetParam(), Vec3::Zero());
  const int thrown = add_grain(model, GetParam(), Vec3(0.0, 0.0, 0.03));
  if (GetParam() == BodyKind::kRigid) {
    model.rigid_bodies[1].v = Vec3(0.0, 0.0, -5.0);
  } else {
    const Body& body = model.bodies[thrown];
    model.particles.v.middleRows(body.first_particle, body.particle_count).col(2).setConstant(-5.0);
  }
  Solver solver(model, scene_settings(GetParam(), 1.0 / 30.0, 20));
  int most_candidates = 0;
  for (int k = 0; k < 3; ++k) {
    solver.step();
    most_candidates = std::max(most_candidates, solver.contacts()->statistics().candidates);
  }
  EXPECT_GT(body_centre(model, thrown).z(), body_centre(model, target).z() + 0.9 * kGrainThickness);
  // Padded by 5 m/s over a broad-phase interval, the pair's reach holds every sphere pair (100,
  // listed before): more than a substep's search over the two grains' spheres, so it is
  // searched in each substep instead, and lists none.
  EXPECT_EQ(most_candidates, 0);
}

INSTANTIATE_TEST_SUITE_P(Kinds, GrainContact, ::testing::Values(BodyKind::kRigid, BodyKind::kSoft), kind_name);

TEST(Colliders, SignedDistancesHaveUnitGradientsMatchingFiniteDifferences) {
  Collider sphere, box, capsule;
  sphere.shape = ColliderShape::kSphere, sphere.radius = 0.3;
  box.shape = ColliderShape::kBox, box.half_extents = Vec3(0.2, 0.3, 0.1);
  capsule.shape = ColliderShape::kCapsule, capsule.radius = 0.1, capsule.half_length = 0.25;
  const Vec3 points[] = {{0.41, -0.2, 0.13}, {0.05, 0.02, -0.03}, {-0.3, 0.35, 0.4}, {0.1, -0.05, 0.2}};
  for (const Collider& c : {sphere, box, capsule})
    for (const Vec3& p : points) {
      const SignedDistance sd = local_signed_distance(c, p);
      EXPECT_NEAR(sd.normal.norm(), 1.0, 1e-12);
      const double e = 1e-7;
      Vec3 gradient;
      for (int k = 0; k < 3; ++k)
        gradient[k] = (local_signed_distance(c, p + e * Vec3::Unit(k)).distance -
                       local_signed_distance(c, p - e * Vec3::Unit(k)).distance) / (2 * e);
      EXPECT_LT((gradient - sd.normal).norm(), 1e-6) << "shape " << static_cast<int>(c.shape);
    }
  EXPECT_NEAR(local_signed_distance(box, Vec3(0.5, 0.0, 0.0)).distance, 0.3, 1e-15);
  EXPECT_NEAR(local_signed_distance(capsule, Vec3(0.0, 0.0, -0.5)).distance, 0.15, 1e-15);
}

TEST_P(GrainContact, WakesAndFallsWhenItsColliderIsRemoved) {
  // A grain asleep on a shelf 5 cm up; the shelf is removed at t = 2.5 s (a mould taken away):
  // the grain must wake, fall freely and land on the ground.
  Model model;
  const int grain = add_grain(model, GetParam(), Vec3(0.0, 0.0, 0.05 + 1e-4));
  Collider shelf = half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4);
  shelf.motion.front().translation = Vec3(0.0, 0.0, 0.05);
  shelf.removal_time = 2.5;
  model.colliders = {half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4), shelf};
  model.sleep.enabled = true;
  Solver solver(model, scene_settings(GetParam(), 1.0 / 30.0, 80));
  while (solver.time() < 2.4) solver.step();
  ASSERT_TRUE(model.bodies[grain].asleep);
  const double shelf_height = body_centre(model, grain).z();
  EXPECT_GT(shelf_height, 0.05);
  // The frame that ends at the removal wakes it; the shelf holds it until then.
  while (solver.time() < 2.5 - 1e-9) solver.step();
  EXPECT_FALSE(model.bodies[grain].asleep);
  EXPECT_NEAR(body_centre(model, grain).z(), shelf_height, 1e-6);
  // Then one frame of free fall: N substeps of symplectic Euler from a speed v₀ fall
  // −v₀ Δt + ½ g Δt² (1 + 1/N). (Woken on the shelf, a soft grain's spheres ring on it: v₀ is
  // some 10 µm/s, up or down.)
  const double v0 = linear_momentum(model).z() / total_mass(model);
  const double start = body_centre(model, grain).z();
  solver.step();
  const int n = scene_settings(GetParam(), 1.0 / 30.0, 80).substeps;
  EXPECT_NEAR(start - body_centre(model, grain).z(), -v0 / 30.0 + 0.5 * 9.81 / (30.0 * 30.0) * (1.0 + 1.0 / n), 1e-9);
  for (int k = 0; k < 30; ++k) solver.step();
  EXPECT_LT(body_centre(model, grain).z(), 0.01);  // on the ground
  EXPECT_GT(lowest_point(model, grain), -0.01 * kGrainThickness);
  Collider bad = shelf;
  bad.removal_time = 0.0;
  EXPECT_THROW(validate(bad, 1), std::invalid_argument);
}

TEST(Colliders, KeyframesInterpolateAndBadCollidersAreRefused) {
  Collider moving;
  moving.motion = {{0.0, Vec3::Zero(), Quat::Identity()}, {2.0, Vec3(0.0, 0.0, 1.0), Quat::Identity(), 3.0}};
  EXPECT_NEAR(collider_pose(moving, 0.5).translation.z(), 0.25, 1e-15);
  EXPECT_NEAR(collider_pose(moving, 0.5).scale, 1.5, 1e-15);
  EXPECT_NEAR(collider_pose(moving, 5.0).translation.z(), 1.0, 1e-15);
  Collider bad = moving;
  bad.motion[1].time = 0.0;
  EXPECT_THROW(validate(bad, 3), std::invalid_argument);
  for (const double scale : {0.0, -1.0, double(INFINITY)}) {
    bad = moving;
    bad.motion[1].scale = scale;
    EXPECT_THROW(validate(bad, 3), std::invalid_argument) << scale;
  }
  bad = moving;
  bad.static_friction = 0.2, bad.dynamic_friction = 0.3;
  EXPECT_THROW(validate(bad, 3), std::invalid_argument);
  bad = moving;
  bad.shape = ColliderShape::kSphere, bad.radius = -1.0;
  EXPECT_THROW(validate(bad, 3), std::invalid_argument);
}

TEST(Colliders, AScaledPoseScalesTheSignedDistanceAboutTheFramesOrigin) {
  // A unit box scaled by 2 about its centre at (1, 0, 0), turned a quarter about z: the world
  // distance of a point is that to a box of half extents 2, whichever way it is read.
  Collider box;
  box.shape = ColliderShape::kBox;
  box.half_extents = Vec3::Ones();
  const ColliderKeyframe pose{0.0, Vec3(1.0, 0.0, 0.0), Quat(Eigen::AngleAxisd(0.5 * M_PI, Vec3::UnitZ())), 2.0};
  for (const Vec3& world : {Vec3(1.0, 0.0, 3.5), Vec3(4.0, 0.5, 0.0), Vec3(1.5, 0.0, 0.0)}) {
    const Vec3 local = to_local(pose, world);
    EXPECT_LT((to_world(pose, local) - world).norm(), 1e-15);
    const SignedDistance d = posed_signed_distance(box, pose, local);
    const Vec3 q = (world - pose.translation).cwiseAbs() - Vec3::Constant(2.0);
    const double expected = (q.array() > 0.0).any() ? q.cwiseMax(0.0).norm() : q.maxCoeff();
    EXPECT_NEAR(d.distance, expected, 1e-14) << world.transpose();
    // The surface point under it, local − (φ / scale) n, is on the scaled box.
    const Vec3 surface = to_world(pose, local - (d.distance / pose.scale) * d.normal);
    EXPECT_NEAR(posed_signed_distance(box, pose, to_local(pose, surface)).distance, 0.0, 1e-14);
  }
}

TEST_P(GrainContact, RidesUpOnAGrowingBox) {
  // A slab of half thickness d under the grain grows to 1.5 times its size about its centre in
  // 1 s: its top, and the grain resting on it, rise by d / 2 at 5 mm/s, the grain never deeper
  // in it than 1% of its thickness.
  const double d = 0.01;
  Model model;
  const int grain = add_grain(model, GetParam(), Vec3::Zero());
  Collider slab;
  slab.shape = ColliderShape::kBox;
  slab.half_extents = Vec3(0.05, 0.05, d);
  const ColliderKeyframe rest{0.0, Vec3(0.0, 0.0, -d), Quat::Identity()};
  slab.motion = {rest, rest, {1.2, rest.translation, Quat::Identity(), 1.5}};
  slab.motion[1].time = 0.2;
  model.colliders.push_back(slab);
  Solver solver(model, scene_settings(GetParam(), 1.0 / 300.0, 10));
  double deepest = 0.0;
  for (int k = 0; k < 450; ++k) {
    solver.step();
    const ColliderKeyframe pose = collider_pose(slab, solver.time());
    if (k > 30) deepest = std::max(deepest, pose.translation.z() + d * pose.scale - lowest_point(model, grain));
  }
  EXPECT_NEAR(lowest_point(model, grain), 0.5 * d, 0.01 * kGrainThickness);
  EXPECT_LT(deepest, 0.01 * kGrainThickness);
}

TEST(Colliders, AColliderHeldBetweenTwoEqualKeyframesHasExactlyThatPose) {
  // A lid held before it presses: (1 − s) a + s a is not a in the last bit, and a pose that
  // differs by a bit is a collider in motion, which wakes every grain it reaches each substep.
  Collider held;
  const ColliderKeyframe pose{0.0, Vec3(0.0, 0.0, 0.1155), Quat(Eigen::AngleAxisd(-0.5 * M_PI, Vec3::UnitX()))};
  held.motion = {pose, pose, {4.0, Vec3(0.0, 0.0, 0.2), Quat::Identity()}};
  held.motion[1].time = 3.3;
  for (const double t : {0.1, 0.7, 1.3, 2.9, 3.2999}) {
    const ColliderKeyframe at = collider_pose(held, t);
    EXPECT_TRUE(at.translation == pose.translation) << t;
    EXPECT_TRUE(at.rotation.coeffs() == pose.rotation.coeffs()) << t;
  }
}

}  // namespace
}  // namespace rice::xpbd

namespace rice::xpbd {
namespace {

TEST_P(GrainContact, RidesAMovingPlateByStaticFriction) {
  // A plate moving at 0.1 m/s along x carries a grain resting on it (μ_s = 0.5): the grain's
  // speed reaches the plate's and its offset on the plate stays put once it sticks.
  Model model;
  const int grain = add_grain(model, GetParam(), Vec3(0.0, 0.0, 0.0));
  Collider plate;
  plate.shape = ColliderShape::kBox;
  plate.half_extents = Vec3(0.5, 0.05, 0.005);
  plate.static_friction = 0.5;
  plate.dynamic_friction = 0.4;
  plate.motion = {{0.0, Vec3(0.0, 0.0, -0.005), Quat::Identity()}, {10.0, Vec3(1.0, 0.0, -0.005), Quat::Identity()}};
  model.colliders.push_back(plate);
  Solver solver(model, scene_settings(GetParam(), 1.0 / 300.0, 10));
  for (int k = 0; k < 150; ++k) solver.step();
  const double offset = body_centre(model, grain).x() - collider_pose(plate, solver.time()).translation.x();
  for (int k = 0; k < 150; ++k) solver.step();
  const double later = body_centre(model, grain).x() - collider_pose(plate, solver.time()).translation.x();
  EXPECT_LT(std::abs(later - offset), 1e-6);
  EXPECT_GT(body_centre(model, grain).x(), 0.9 * 0.1);  // it travelled with the plate (1 s at 0.1 m/s)
}

/// One contact substep [time, time + h] whose prediction moves `grain` by `step`; returns how
/// far the contacts then moved its centre.
Vec3 contact_substep(Model& model, ContactSolver& contacts, int grain, double time, double h, const Vec3& step) {
  const Positions start = model.particles.x;
  model.particles.x.rowwise() += step.transpose();
  const Vec3 predicted = body_centre(model, grain);
  contacts.begin_substep(time, h, start);
  contacts.project(start);
  contacts.end_substep(false);
  return body_centre(model, grain) - predicted;
}

TEST(GrainContact, FrictionTakesBackTheSlipOfAFlightBetweenTwoTouches) {
  // A soft grain's spheres chattering on a plane at the substep rate: down onto it in one
  // substep, forward d and up off it in the next, straight down onto it in the third. Friction,
  // when they touch again, takes back the flight's slip, up to μ_k λ_n. (Its anchors reset in
  // the flight, it saw no slip, and in press.toml a bonded pair slid away over the plate at a
  // constant 7.7 cm/s.)
  Model model;
  // Radii of every substep: one updated between the anchors and the touch would move the
  // contact point by a few 1e-8 m, over this test's 1e-12.
  model.contact.radius_interval = 0.0;
  const int grain = add_grain(model, BodyKind::kSoft, Vec3::Zero());  // its spheres on z = 0
  Collider plane;
  plane.static_friction = 0.5;
  plane.dynamic_friction = 0.4;
  model.colliders.push_back(plane);
  ContactSolver contacts(model);
  const double h = 1e-4, d = 5e-6, lift = 1e-6;
  contacts.find_candidates(0.0, 7 * h);
  const auto substep = [&](int k, const Vec3& step) { return contact_substep(model, contacts, grain, k * h, h, step); };
  ASSERT_GT(substep(0, Vec3(0.0, 0.0, -lift)).z(), 0.9 * lift);  // the first touch, anchored
  ASSERT_EQ(substep(1, Vec3(d, 0.0, lift)), Vec3::Zero());        // the flight
  const Vec3 moved = substep(2, Vec3(0.0, 0.0, -2.0 * lift));    // the touch, 1 µm into the plane
  ASSERT_GT(moved.z(), 0.0);  // pushed out
  // Each contact's friction impulse is μ_k its normal one, through the same weights.
  EXPECT_NEAR(-moved.x(), 0.4 * moved.z(), 1e-6 * moved.z());
  EXPECT_NEAR(moved.y(), 0.0, 1e-12);
  // What friction could not take back has slid, and the anchors start again there: the next
  // flight's slip counts (anchors dropped, it went uncounted), and after a flight straight up
  // a touch straight down finds none (anchors kept, it took more of the first flight back).
  ASSERT_EQ(substep(3, Vec3(d, 0.0, lift + moved.z())), Vec3::Zero());
  const Vec3 again = substep(4, Vec3(0.0, 0.0, -2.0 * lift));
  EXPECT_NEAR(-again.x(), 0.4 * again.z(), 1e-6 * again.z());
  ASSERT_EQ(substep(5, Vec3(0.0, 0.0, lift + again.z())), Vec3::Zero());
  const Vec3 third = substep(6, Vec3(0.0, 0.0, -2.0 * lift));
  ASSERT_GT(third.z(), 0.0);
  EXPECT_NEAR(third.x(), 0.0, 1e-12);
}

TEST(GrainContact, FrictionSeesNoSlipBeforeTheFirstTouch) {
  // A soft grain gliding in sideways d above a plane, then down onto it: its first touch has
  // slipped nothing. (Anchored in the glide, friction took d back on landing; in a shari such
  // anchors, a gap apart, kept a 0.5 mm overlap and 97 of 270 grains awake.)
  Model model;
  const int grain = add_grain(model, BodyKind::kSoft, Vec3(0.0, 0.0, 2e-6));  // 2 µm up
  Collider plane;
  plane.static_friction = 0.5;
  plane.dynamic_friction = 0.4;
  model.colliders.push_back(plane);
  ContactSolver contacts(model);
  const double h = 1e-4, d = 5e-6;
  contacts.find_candidates(0.0, 2 * h);
  const auto substep = [&](int k, const Vec3& step) { return contact_substep(model, contacts, grain, k * h, h, step); };
  ASSERT_EQ(substep(0, Vec3(d, 0.0, -1e-6)), Vec3::Zero());  // the glide, 1 µm above
  const Vec3 moved = substep(1, Vec3(0.0, 0.0, -2e-6));      // the landing, 1 µm in
  ASSERT_GT(moved.z(), 0.0);
  EXPECT_NEAR(moved.x(), 0.0, 1e-12);
}

class BroadPhase : public ::testing::TestWithParam<int> {};

TEST_P(BroadPhase, FindsExactlyTheOverlappingPairs) {
  // Random boxes, some of them touching exactly (a closed box overlaps on its faces), against
  // every pair tested; below and above the count from which the BVH takes over from the sweep.
  const int n = GetParam();
  std::vector<Box> boxes;
  unsigned state = 12345;
  const auto uniform = [&] { return (state = state * 1103515245u + 12345u) / 4294967296.0; };
  const double side = std::cbrt(n / 300.0);
  for (int k = 0; k < n; ++k) {
    const Vec3 lower(side * uniform(), side * uniform(), 0.3 * side * uniform());
    boxes.push_back({lower, lower + Vec3(0.05 + 0.05 * uniform(), 0.05, 0.02)});
    if (k % 10 == 9) boxes.push_back({boxes.back().upper, boxes.back().upper + Vec3(0.01, 0.02, 0.03)});
  }
  std::vector<std::pair<int, int>> expected;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j)
      if (boxes[i].overlaps(boxes[j])) expected.emplace_back(i, j);
  EXPECT_GT(expected.size(), static_cast<size_t>(n / 10));
  EXPECT_EQ(overlapping_pairs(boxes), expected);
  EXPECT_EQ(overlapping_pairs_by_sweep(boxes), expected);
  EXPECT_EQ(overlapping_pairs_by_bvh(boxes), expected);
}

INSTANTIATE_TEST_SUITE_P(Counts, BroadPhase, ::testing::Values(300, kBvhBroadPhaseFrom + 500));

}  // namespace
}  // namespace rice::xpbd

namespace rice::xpbd {
namespace {

/// A grain hanging under a pinned one, touching it, with bonds of `strength` times its
/// weight; returns how far it fell in 0.5 s.
double hanging_drop(BodyKind kind, double strength_over_weight, int* bonds) {
  Model model;
  model.contact.cohesion = true;
  const int top = add_grain(model, BodyKind::kRigid, Vec3(0.0, 0.0, kGrainThickness));
  model.rigid_bodies[0].inverse_mass = 0.0;  // pinned
  model.rigid_bodies[0].inverse_inertia.setZero();
  const int bottom = add_grain(model, kind, Vec3::Zero());
  const double weight = kGrainDensity * kGrainLength * kGrainWidth * kGrainThickness * 9.81;
  model.bodies[top].bond_strength = model.bodies[bottom].bond_strength = strength_over_weight * weight;
  Solver solver(model, scene_settings(kind, 1.0 / 300.0, 10));
  const double z0 = body_centre(model, bottom).z();
  for (int k = 0; k < 150; ++k) solver.step();
  *bonds = solver.contacts()->statistics().bonds;
  return z0 - body_centre(model, bottom).z();
}

TEST_P(GrainContact, ABondAboveTheWeightHoldsAHangingGrainAndOneBelowBreaks) {
  int bonds = 0;
  EXPECT_LT(hanging_drop(GetParam(), 2.0, &bonds), 0.05 * kGrainThickness);
  EXPECT_GE(bonds, 3);  // a patch: the grain does not swing
  EXPECT_GT(hanging_drop(GetParam(), 0.5, &bonds), 0.5);  // free fall: 1.2 m in 0.5 s
  EXPECT_EQ(bonds, 0);
}

/// The deepest overlap of a sphere of body a with one of body b [m] (0 if none).
double deepest_overlap(const Model& model, int a, int b) {
  const Body& body_a = model.bodies[a];
  const Body& body_b = model.bodies[b];
  double deepest = 0.0;
  for (int i = 0; i < body_a.sphere_count(); ++i)
    for (int j = 0; j < body_b.sphere_count(); ++j)
      deepest = std::max(deepest, sphere_radius(model, body_a, i) + sphere_radius(model, body_b, j) -
                                      (sphere_centre(model, body_a, i) - sphere_centre(model, body_b, j)).norm());
  return deepest;
}

/// A box collider of `half_extents` at `start` until 2 s, then moving straight to `end` by
/// `until`, where it stays.
Collider box_moving_at_2s(const Vec3& half_extents, const Vec3& start, const Vec3& end, double until) {
  Collider box;
  box.shape = ColliderShape::kBox;
  box.half_extents = half_extents;
  box.motion = {{0.0, start, Quat::Identity()}, {2.0, start, Quat::Identity()}, {until, end, Quat::Identity()}};
  return box;
}

/// Steps to `until`; returns the deepest overlap of bodies 0 and 1 on the way, and whether
/// body 1 was awake after some step (`woke`).
double deepest_overlap_until(Solver& solver, const Model& model, double until, bool* woke = nullptr) {
  double deepest = 0.0;
  while (solver.time() < until) {
    solver.step();
    deepest = std::max(deepest, deepest_overlap(model, 0, 1));
    if (woke) *woke = *woke || !model.bodies[1].asleep;
  }
  return deepest;
}

TEST(GrainContact, AGrainWokenByAMovingColliderMeetsItsSleepingNeighbour) {
  // Two soft grains stacked on the ground, asleep; a box comes down at 5 cm/s and presses the
  // top one 0.2 mm. The box wakes it, and its contacts with the sleeping grain under it come
  // with it. (Looked for before the box woke it, the pair of two sleeping grains was skipped
  // for the broad-phase interval, and the box pushed one grain 0.11 mm into the other.)
  Model model;
  model.sleep.enabled = true;
  model.contact.cohesion = true;  // sphere on sphere, the top grain would roll off
  add_grain(model, BodyKind::kSoft, Vec3::Zero());
  add_grain(model, BodyKind::kSoft, Vec3(0.0, 0.0, kGrainThickness));
  const double weight = kGrainDensity * kGrainLength * kGrainWidth * kGrainThickness * 9.81;
  for (Body& body : model.bodies) body.bond_strength = 20.0 * weight;
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  const Vec3 half_extents(0.01, 0.01, 0.002);
  const Vec3 above(0.5 * kGrainLength, 0.5 * kGrainWidth, 2.0 * kGrainThickness + half_extents.z());
  model.colliders.push_back(
      box_moving_at_2s(half_extents, above + Vec3(0.0, 0.0, 5e-3), above - Vec3(0.0, 0.0, 2e-4), 2.104));
  Solver solver(model, scene_settings(BodyKind::kSoft, 1.0 / 30.0, 80));
  while (solver.time() < 2.0 - 1e-9) solver.step();
  ASSERT_TRUE(model.bodies[0].asleep && model.bodies[1].asleep);
  const double top = body_centre(model, 1).z();
  bool woke = false;
  const double deepest = deepest_overlap_until(solver, model, 2.3, &woke);
  EXPECT_TRUE(woke);
  EXPECT_LT(body_centre(model, 1).z(), top - 1e-4);  // pressed
  EXPECT_LT(deepest, 8e-5);  // 5.5e-5 as the box stops (1.1e-4 before)
}

TEST(GrainContact, AGrainPushedByAMovingColliderMeetsANeighbourAGapAway) {
  // Two soft grains asleep side by side on the ground, 0.1 mm apart; a wall comes in at 5 cm/s
  // and pushes the first 0.3 mm, into the second. The wall can push a grain as far as it
  // moves in a broad-phase interval (0.25 mm), so the pushed grain's neighbours that far away
  // are candidates. (With only its own motion bound, zero at rest, the pair was not, and the
  // first grain went 43 µm into the second.)
  Model model;
  model.sleep.enabled = true;
  add_grain(model, BodyKind::kSoft, Vec3::Zero());
  add_grain(model, BodyKind::kSoft, Vec3(0.0, kGrainWidth + 1e-4, 0.0));
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  const Vec3 half_extents(0.01, 0.002, 0.005);
  const Vec3 touching(0.5 * kGrainLength, -half_extents.y(), 0.0);  // its face on the grain
  model.colliders.push_back(
      box_moving_at_2s(half_extents, touching - Vec3(0.0, 1e-3, 0.0), touching + Vec3(0.0, 3e-4, 0.0), 2.026));
  Solver solver(model, scene_settings(BodyKind::kSoft, 1.0 / 30.0, 80));
  while (solver.time() < 2.0 - 1e-9) solver.step();
  ASSERT_TRUE(model.bodies[0].asleep && model.bodies[1].asleep);
  const double second = body_centre(model, 1).y();
  const double deepest = deepest_overlap_until(solver, model, 2.2);
  EXPECT_GT(body_centre(model, 1).y(), second + 1e-4);  // pushed on by the first
  EXPECT_LT(deepest, 1e-5);  // none (4.3e-5 before)
}

TEST_P(GrainContact, BondsOfTwoSleepingGrainsHoldWithoutForce) {
  // A grain stacked on another on the ground, bonded at 20 weights, both falling asleep: a
  // bond whose two bodies sleep moves nothing and carries no force, so it keeps (a bond
  // solved with no mass on either side read its stretch over its compliance as a force, and
  // sleeping piles came apart: the bunny slumped when its mould went).
  Model model;
  model.contact.cohesion = true;
  model.sleep.enabled = true;
  add_grain(model, GetParam(), Vec3(0.0, 0.0, 0.5 * kGrainThickness));
  add_grain(model, GetParam(), Vec3(0.0, 0.0, 1.5 * kGrainThickness));
  const double weight = kGrainDensity * kGrainLength * kGrainWidth * kGrainThickness * 9.81;
  for (Body& body : model.bodies) body.bond_strength = 20.0 * weight;
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  Solver solver(model, scene_settings(GetParam(), 1.0 / 30.0, 80));
  for (int frame = 0; frame < 60; ++frame) solver.step();
  EXPECT_TRUE(model.bodies[0].asleep && model.bodies[1].asleep);
  EXPECT_GE(solver.contacts()->statistics().bonds, 3);
  EXPECT_EQ(solver.contacts()->statistics().bonds_broken, 0);
}

TEST_P(GrainContact, ABondFormsAtItsGapWithoutSnappingItShut) {
  // Two grains 8 µm apart (within the bond distance and the contact margin), no gravity:
  // bonds form at that gap and hold it. Snapping the gap shut in one substep pulled harder
  // than the weight the pair holds, and the pair broke as it formed.
  Model model;
  model.gravity.setZero();
  model.contact.cohesion = true;
  const double gap = 8e-6;
  add_grain(model, GetParam(), Vec3::Zero());
  add_grain(model, GetParam(), Vec3(0.0, 0.0, kGrainThickness + gap));
  const double weight = kGrainDensity * kGrainLength * kGrainWidth * kGrainThickness * 9.81;
  for (Body& body : model.bodies) body.bond_strength = weight;
  const double apart = (body_centre(model, 1) - body_centre(model, 0)).norm();
  Solver solver(model, scene_settings(GetParam(), 1.0 / 30.0, 80));
  for (int frame = 0; frame < 10; ++frame) solver.step();
  EXPECT_GE(solver.contacts()->statistics().bonds, 3);
  EXPECT_EQ(solver.contacts()->statistics().bonds_broken, 0);
  EXPECT_NEAR((body_centre(model, 1) - body_centre(model, 0)).norm(), apart, 0.1 * gap);
}

TEST(SphereAnchor, AnImpulseMovesTheCentreByItsInverseMassAndTheDisplacementIsTheCentresMotion) {
  // Δx_k = w_k b_k p moves Σ b_k x_k by (Σ b_k² w_k) p: what contact takes as the inverse mass
  // a soft sphere shows at its centre. And the displacement is the difference of the centres.
  Model model;
  const Body& body = model.bodies[add_grain(model, BodyKind::kSoft, Vec3::Zero())];
  std::mt19937 random(7);
  std::normal_distribution<double> jitter(0.0, 1e-4);
  for (int i = 0; i < model.particles.size(); ++i)
    model.particles.x.row(i) += Vec3(jitter(random), jitter(random), jitter(random)).transpose();
  const Vec3 p(2e-6, -1e-6, 3e-6);
  for (const SphereAnchor& anchor : body.anchors) {
    const Positions before = model.particles.x;
    const Vec3 centre = anchor.at(before);
    const double w = anchor.inverse_mass(model.particles.w);
    ASSERT_GT(w, 0.0);
    anchor.apply(model.particles.x, model.particles.w, p);
    EXPECT_LT((anchor.at(model.particles.x) - centre - w * p).norm(), 1e-12 * (w * p).norm());
    EXPECT_LT((anchor.displacement(model.particles.x, before) - (anchor.at(model.particles.x) - centre)).norm(),
              1e-12 * (w * p).norm());
  }
}

TEST(SphereRadius, ASoftGrainsSpheresThinWithItsSmallestStretchOnlyAndVanishInsideOut) {
  // x ↦ R diag(1, 1, k) x: every tet's F has singular values (1, 1, k), so each sphere's
  // radius is min(1, k) of its rest radius, whatever the rotation R (to 1e-8 relative: the
  // closed-form eigenvalues of FᵀF lose digits where two are equal).
  Model model;
  const int grain = add_grain(model, BodyKind::kSoft, Vec3::Zero());
  const Body& body = model.bodies[grain];
  const Positions rest = model.particles.x;
  const Mat3 turn = Eigen::AngleAxisd(0.5, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (const double k : {0.6, 1.0, 1.5}) {
    const Mat3 map = turn * Eigen::Vector3d(1.0, 1.0, k).asDiagonal();
    model.particles.x = rest * map.transpose();
    for (int s = 0; s < body.sphere_count(); ++s)
      EXPECT_NEAR(sphere_radius(model, body, s), std::min(1.0, k) * body.radii[s], 1e-8 * body.radii[s]) << "k = " << k;
  }
  // Stretched every way (singular values 1.1, 1.2, 1.5), the spheres keep their rest radii.
  model.particles.x = rest * (turn * Eigen::Vector3d(1.1, 1.2, 1.5).asDiagonal()).transpose();
  for (int s = 0; s < body.sphere_count(); ++s) EXPECT_EQ(sphere_radius(model, body, s), body.radii[s]);
  // Stretched two ways and squeezed the third (1.3, 1.2, 0.9): the smallest stretch decides.
  model.particles.x = rest * (turn * Eigen::Vector3d(1.3, 1.2, 0.9).asDiagonal()).transpose();
  for (int s = 0; s < body.sphere_count(); ++s)
    EXPECT_NEAR(sphere_radius(model, body, s), 0.9 * body.radii[s], 1e-8 * body.radii[s]);
  // Mirrored (1, 1, −1): every tet inside out, so its signed smallest stretch is −1 and each
  // sphere shrinks to its centre, though FᵀF is that of the rest shape.
  model.particles.x = rest * (turn * Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal()).transpose();
  for (int s = 0; s < body.sphere_count(); ++s) EXPECT_EQ(sphere_radius(model, body, s), 0.0);
}

/// One soft grain dropped onto the ground under a sudden load of 300 times its weight (g =
/// 3000 m/s²), which squeezes it by a tenth; its spheres' radii updated once a
/// `radius_interval`. Returns each step's thinnest sphere radius and centre height.
std::vector<Vec2> loaded_grain(double radius_interval) {
  Model model;
  model.contact.radius_interval = radius_interval;
  model.gravity = Vec3(0.0, 0.0, -3000.0);
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  // Damped as a scene's grains are (eq. 4 at a 240 min soak: 1.8 ms).
  const int grain = add_soft_body(model, grain_mesh(Vec3::Zero()), kGrainDensity, lame_from_young_poisson(5e4, 0.3),
                                  1.8e-3, grain_spheres(Vec3::Zero()));
  Solver solver(model, scene_settings(BodyKind::kSoft, 1.0 / 300.0, 1));
  std::vector<Vec2> trace;
  while (solver.time() < 0.15) {
    solver.step();
    double thinnest = INFINITY;
    for (int s = 0; s < model.bodies[grain].sphere_count(); ++s)
      thinnest = std::min(thinnest, sphere_radius(model, model.bodies[grain], s));
    trace.push_back({thinnest, body_centre(model, grain).z()});
  }
  return trace;
}

TEST(SphereRadius, RadiiHeldForAnIntervalFollowASuddenLoadAsThoseOfEverySubstep) {
  // Radii held for 0.5 ms (ContactSettings::radius_interval: 4 substeps of 1.45e-4 s here)
  // against radii of every substep, through the load's first millisecond and the rest after.
  const std::vector<Vec2> every = loaded_grain(0.0), held = loaded_grain(ContactSettings{}.radius_interval);
  ASSERT_EQ(every.size(), held.size());
  double radius_error = 0.0, centre_error = 0.0;
  for (size_t k = 0; k < every.size(); ++k) {
    radius_error = std::max(radius_error, std::abs(every[k][0] - held[k][0]));
    centre_error = std::max(centre_error, std::abs(every[k][1] - held[k][1]));
  }
  const double rest_radius = 0.5 * kGrainThickness;
  EXPECT_LT(every.back()[0], 0.95 * rest_radius);  // the load does thin the spheres
  EXPECT_LT(radius_error, 0.01 * rest_radius);
  EXPECT_LT(centre_error, 0.01 * rest_radius);
  RecordProperty("largest_radius_difference_m", std::to_string(radius_error));
  RecordProperty("largest_centre_difference_m", std::to_string(centre_error));
}

TEST(Penetration, MeasuresAKnownOverlapAndDepthIntoACollider) {
  // Grain b's spheres sit straight above grain a's, 1.7 mm apart: spheres of radius 1 mm
  // overlap by 0.3 mm. The plane z = 1e-4 m cuts 0.1 mm into a's lowest spheres.
  Model model;
  add_grain(model, BodyKind::kRigid, Vec3::Zero());
  add_grain(model, BodyKind::kSoft, Vec3(0.0, 0.0, kGrainThickness - 3e-4));
  model.colliders.push_back(half_space(Vec3::UnitZ(), 1e-4, 0.5, 0.4));
  const Penetration p = deepest_penetration(model, 0.0);
  EXPECT_NEAR(p.between_bodies, 3e-4, 1e-12);
  EXPECT_NEAR(p.into_colliders, 1e-4, 1e-12);
  EXPECT_NEAR(p.deepest(), 3e-4, 1e-12);
}

/// Two rigid grains stacked and touching, whose one bond has just broken (any pull breaks it):
/// `touching` is their touch, to hand to each substep's begin.
struct BrokenPair {
  static constexpr double h = 1e-4;
  Model model;
  CohesionBonds bonds;
  std::vector<CohesionBonds::Touch> touching;

  explicit BrokenPair(double heal_time) {
    add_grain(model, BodyKind::kRigid, Vec3::Zero());
    add_grain(model, BodyKind::kRigid, Vec3(0.0, 0.0, kGrainThickness));
    for (Body& body : model.bodies) body.bond_strength = 1e-9;  // [N]
    model.contact.bond_heal_time = heal_time;
    for (RigidBody& rigid : model.rigid_bodies) rigid.remember_pose();
    const Body& bottom = model.bodies[0];
    const Vec3 p = sphere_centre(model, bottom, 0) + sphere_radius(model, bottom, 0) * Vec3::UnitZ();
    touching = {{{0, 1, 0, 0}, p, p}};
    bonds.begin_substep(model, touching, model.particles.x);
    EXPECT_EQ(bonds.count(), 1);
    model.rigid_bodies[1].x.z() += 1e-5;  // pulled: the bond's projection carries a force
    bonds.project(model, h);
    bonds.end_substep(h);
    model.rigid_bodies[1].x.z() -= 1e-5;
    EXPECT_EQ(bonds.count(), 0);
    EXPECT_EQ(bonds.broken(), 1);
  }
  /// One substep with the pair touching or apart; returns whether it is bonded in it.
  bool substep(bool touch) {
    bonds.begin_substep(model, touch ? touching : std::vector<CohesionBonds::Touch>{}, model.particles.x);
    const bool bonded = bonds.count() > 0;
    bonds.end_substep(h);
    return bonded;
  }
};

TEST(GrainContact, ABrokenPairBondsAgainOnceItHasTouchedForTheHealTime) {
  // 2 ms at 0.1 ms substeps: bonded again at the 20th substep of touching (21st by round-off).
  BrokenPair pair(2e-3);
  int healed = 0;
  while (healed < 1000 && !pair.substep(true)) ++healed;
  EXPECT_GE(healed + 1, 19);
  EXPECT_LE(healed + 1, 21);
}

TEST(GrainContact, ABrokenPairStaysUnbondedWhileItTouchesAndBondsOnceItHasSeparated) {
  // Without a heal time a pair pulled apart is not glued back before it moves.
  BrokenPair pair(INFINITY);
  for (int k = 0; k < 1000; ++k) ASSERT_FALSE(pair.substep(true)) << k;
  EXPECT_FALSE(pair.substep(false));  // apart for a substep
  EXPECT_TRUE(pair.substep(true));
}

TEST(GrainContact, CohesionOffFormsNoBonds) {
  Model model;
  add_grain(model, BodyKind::kRigid, Vec3::Zero());
  add_grain(model, BodyKind::kRigid, Vec3(0.0, 0.0, kGrainThickness));
  for (Body& body : model.bodies) body.bond_strength = 1.0;
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  Solver solver(model, scene_settings(BodyKind::kRigid, 1.0 / 300.0, 10));
  for (int k = 0; k < 10; ++k) solver.step();
  EXPECT_GT(solver.contacts()->statistics().contacts, 0);
  EXPECT_EQ(solver.contacts()->statistics().bonds, 0);
}

}  // namespace
}  // namespace rice::xpbd

namespace rice::xpbd {
namespace {

/// φ(p) = n·p − d sampled on a grid: trilinear interpolation reproduces a linear field.
DistanceGrid plane_grid(const Vec3& n, double d) {
  DistanceGrid grid;
  grid.origin = Vec3(-0.01, -0.02, -0.005);
  grid.spacing = 0.002;
  grid.size = Eigen::Vector3i(11, 21, 8);
  for (int k = 0; k < grid.size.z(); ++k)
    for (int j = 0; j < grid.size.y(); ++j)
      for (int i = 0; i < grid.size.x(); ++i)
        grid.values.push_back(static_cast<float>(n.dot(grid.origin + grid.spacing * Vec3(i, j, k)) - d));
  return grid;
}

TEST(DistanceGrid, ReproducesALinearFieldAndItsGradient) {
  const Vec3 n = Vec3(0.3, -0.5, 0.81).normalized();
  const DistanceGrid grid = plane_grid(n, 0.001);
  validate(grid);
  for (const Vec3& p : {Vec3(0.0031, 0.0107, 0.0009), Vec3(-0.0099, -0.0199, -0.0049), Vec3(0.0, 0.0, 0.0)}) {
    const GridSample s = sample(grid, p);
    EXPECT_NEAR(s.distance, n.dot(p) - 0.001, 1e-7);  // float storage
    EXPECT_LT((s.gradient - n).norm(), 1e-5);
  }
  // Beyond the grid: the boundary value plus the distance to the grid.
  const Vec3 beyond(0.05, 0.0, 0.0);
  EXPECT_NEAR(sample(grid, beyond).distance, n.dot(Vec3(0.01, 0.0, 0.0)) - 0.001 + 0.04, 1e-6);
  EXPECT_LT((sample(grid, beyond).gradient - Vec3::UnitX()).norm(), 1e-12);
}

TEST(DistanceGrid, GradientMatchesFiniteDifferencesOfTheInterpolant) {
  DistanceGrid grid = plane_grid(Vec3::UnitZ(), 0.0);
  for (size_t v = 0; v < grid.values.size(); ++v) grid.values[v] += 0.0005f * std::sin(0.7f * v);  // not linear
  const Vec3 p(0.0013, 0.0041, 0.0007);
  const GridSample s = sample(grid, p);
  Vec3 fd;
  const double e = 1e-7;
  for (int a = 0; a < 3; ++a) fd[a] = (sample(grid, p + e * Vec3::Unit(a)).distance - sample(grid, p - e * Vec3::Unit(a)).distance) / (2 * e);
  EXPECT_LT((s.gradient - fd.normalized()).norm(), 1e-6);
}

TEST(DistanceGrid, BadGridsAreRefused) {
  DistanceGrid grid = plane_grid(Vec3::UnitZ(), 0.0);
  grid.values.pop_back();
  EXPECT_THROW(validate(grid), std::invalid_argument);
  grid = plane_grid(Vec3::UnitZ(), 0.0);
  grid.spacing = 0.0;
  EXPECT_THROW(validate(grid), std::invalid_argument);
  grid = plane_grid(Vec3::UnitZ(), 0.0);
  grid.values[3] = NAN;
  EXPECT_THROW(validate(grid), std::invalid_argument);
}

}  // namespace
}  // namespace rice::xpbd

namespace rice::xpbd {
namespace {

TEST(BroadPhase, AGrainReleasedFromItsParkingPlaceIsPaddedByItsSpeedNotItsJump) {
  // A soft grain parked asleep 2 m away is moved in beside a row of resting grains (as an
  // emitter releases one) between two broad phases: its candidate sphere pairs are those of a
  // grain that was there all along. Its jump read as a speed (400 m/s over 5 ms) padded its
  // box by 3 m: it reached every grain, each pair too many spheres to list (none listed, all
  // searched each substep); in the 34,000-grain rice cooker each round of the fill took 5 GB.
  const auto candidates = [](bool released) {
    Model model;
    for (int k = 0; k < 10; ++k) add_grain(model, BodyKind::kSoft, Vec3(0.01 * k, 0.0, 0.0));  // 3 mm gaps
    const Vec3 beside(-kGrainLength - 2e-4, 0.0, 0.0);  // 0.2 mm from the first
    const Vec3 parking(2.0, 0.0, 0.0);
    const int grain = add_grain(model, BodyKind::kSoft, released ? parking : beside);
    model.bodies[grain].asleep = released;
    ContactSolver solver(model);
    solver.find_candidates(0.0, 5e-3);
    if (released) {  // World::release: moved, woken
      const Body& body = model.bodies[grain];
      auto x = model.particles.x.middleRows(body.first_particle, body.particle_count);
      x.rowwise() += (beside - parking).transpose();
      wake(model.bodies[grain]);
    }
    solver.find_candidates(5e-3, 5e-3);
    return solver.statistics().candidates;
  };
  const int in_place = candidates(false);
  EXPECT_GT(in_place, 0);
  EXPECT_EQ(candidates(true), in_place);
}

}  // namespace
}  // namespace rice::xpbd
