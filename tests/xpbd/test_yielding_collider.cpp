// A collider that gives way past a force (collider.hpp: force_limit, next_yield): its rule
// against the hand-computed rates, a lid pressing a grain onto the floor with its limit (the
// force balance: the lid carries its limit, the floor that plus the grain's weight) where a
// kinematic lid crushes it, its return to its keyframes once unloaded, and a checkpoint taken
// mid-press that goes on to the same bits.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/model_health.hpp"
#include "xpbd/solver.hpp"
#include "xpbd/state_archive.hpp"

namespace rice::xpbd {
namespace {

using namespace test_support;

constexpr double kWeight = kGrainDensity * kGrainLength * kGrainWidth * kGrainThickness * 9.81;  // [N]

/// A lid 12 mm square and 2 mm thick over a grain lying on the floor: its bottom 1 mm over the
/// grain at t = 0, brought down by t = 0.1 s to half the grain's thickness over the floor (out
/// of reach of a lid that yields), held there to `hold`, then lifted back by hold + 0.1 s.
Collider pressing_lid(double force_limit, double hold) {
  Collider lid;
  lid.shape = ColliderShape::kBox;
  lid.half_extents = Vec3(6e-3, 6e-3, 1e-3);
  const Vec3 over(0.5 * kGrainLength, 0.5 * kGrainWidth, 0.0);
  const double up = kGrainThickness + 2e-3, down = 0.5 * kGrainThickness + 1e-3;  // its centre
  lid.motion = {{0.0, over + up * Vec3::UnitZ()},
                {0.1, over + down * Vec3::UnitZ()},
                {hold, over + down * Vec3::UnitZ()},
                {hold + 0.1, over + up * Vec3::UnitZ()}};
  lid.force_limit = force_limit;
  lid.static_friction = 0.5;  // as the floor: a grain squeezed without friction shoots out sideways
  lid.dynamic_friction = 0.4;
  return lid;
}

Model pressed_grain(BodyKind kind, double force_limit, double hold) {
  Model model;
  add_grain(model, kind, Vec3::Zero());
  model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.5, 0.4));
  model.colliders.push_back(pressing_lid(force_limit, hold));
  return model;
}

/// 40 substeps a 1/300 s step (83 µs): the lid's back-and-forth under a stiff contact is about
/// v_y h, 4 µm.
SolverSettings press_settings() {
  SolverSettings s;
  s.time_step = 1.0 / 300.0;
  s.substeps = 40;
  s.iterations = 1;
  s.execution = Execution::kSerial;
  return s;
}

TEST(YieldingCollider, FollowsItsRuleForTheRateOfGivingWay) {
  // ṡ = u clamp(ℓ, 0, 1) + v_y clamp(ℓ − 1, −1, 1), s ≥ 0: the lid's keyframes come down at
  // u = 0.02 m/s (2 mm in 0.1 s) until 0.1 s; F_max = 2 N, v_y = 0.05 m/s.
  Collider lid = pressing_lid(2.0, 1.0);
  lid.yield_speed = 0.05;
  const double h = 1e-4, u = 0.02;
  const auto rate = [&](double force, double offset) {
    lid.yield = {0.0, offset, 0.0, force};
    return next_yield(lid, 0.05, h).rate;
  };
  EXPECT_DOUBLE_EQ(rate(0.0, 0.0), 0.0);                 // unloaded at its keyframes: follows them
  EXPECT_NEAR(rate(2.0, 0.0), u, 1e-12);                 // at its limit: stands still
  EXPECT_NEAR(rate(4.0, 0.0), u + 0.05, 1e-12);          // at twice its limit: backs off at v_y
  EXPECT_NEAR(rate(10.0, 0.0), u + 0.05, 1e-12);         // no faster past that
  EXPECT_NEAR(rate(1.0, 1.0), 0.5 * u - 0.025, 1e-12);   // half its limit: slowed by half, returning
  EXPECT_NEAR(rate(0.0, 1e-6), -1e-6 / h, 1e-12);        // back at its keyframes in one substep, no further
  EXPECT_NEAR(rate(-1.0, 1.0), -0.05, 1e-12);            // pulled: returns at v_y, no faster
  // Its pose is the keyframes' moved by s along the axis.
  lid.yield = {0.05, 2e-3, 0.01, 0.0};
  const double s = 2e-3 + 0.01 * 0.02;
  EXPECT_NEAR(yield_offset(lid, 0.07), s, 1e-15);
  EXPECT_NEAR((collider_pose(lid, 0.07).translation - pressing_lid(INFINITY, 1.0).motion[0].translation).z(),
              -0.07 / 0.1 * 2e-3 + s, 1e-12);
}

class PressingLid : public ::testing::TestWithParam<BodyKind> {};

std::string lid_kind_name(const ::testing::TestParamInfo<BodyKind>& info) {
  return info.param == BodyKind::kRigid ? "Rigid" : "Soft";
}

TEST_P(PressingLid, CarriesItsForceLimitWhereAKinematicLidCrushesTheGrain) {
  // Held 0.3 s at a depth it cannot reach, the lid settles where the grain pushes back with its
  // limit, 20 grain weights (mean over the last 0.1 s): the floor carries that plus the weight,
  // the grain stays as thick as it was (to 2%: the soft one, E = 50 kPa, is pressed by 20 W over
  // 7 × 3 mm, a strain of σ/E = 0.9%) and no contact sinks in by 2% of its thickness. The same
  // lid without a limit (its keyframes' way: whatever force it takes) presses the grain to half
  // its thickness, with many times that force: a rigid grain into the floor and the lid.
  const double limit = 20.0 * kWeight;
  for (const double force_limit : {limit, double{INFINITY}}) {
    Model model = pressed_grain(GetParam(), force_limit, 0.4);
    Solver solver(model, press_settings());
    Vec3 floor_load = Vec3::Zero(), lid_load = Vec3::Zero();
    double deepest = 0.0;
    const int steps = 120, averaged = 30;  // 0.4 s; the last 0.1 s
    for (int k = 0; k < steps; ++k) {
      solver.step();
      if (k < steps - averaged) continue;
      floor_load += solver.contacts()->statistics().collider_forces[0] / averaged;
      lid_load += solver.contacts()->statistics().collider_forces[1] / averaged;
      deepest = std::max(deepest, solver.contacts()->statistics().max_penetration);
    }
    const double lid_bottom = collider_pose(model.colliders[1], solver.time()).translation.z() - 1e-3;
    if (std::isfinite(force_limit)) {
      EXPECT_NEAR(lid_load.z(), limit, 0.05 * limit);
      EXPECT_NEAR(-floor_load.z(), limit + kWeight, 0.05 * limit);
      EXPECT_NEAR(lid_bottom, kGrainThickness, 0.02 * kGrainThickness);
      EXPECT_LT(deepest, 0.02 * kGrainThickness);
      EXPECT_EQ(inverted_tets(model), 0);
    } else {
      EXPECT_NEAR(lid_bottom, 0.5 * kGrainThickness, 1e-12);
      EXPECT_GT(-floor_load.z(), 5.0 * limit);
      if (GetParam() == BodyKind::kRigid) {
        EXPECT_GT(deepest, 0.1 * kGrainThickness);
      }
    }
  }
}

TEST_P(PressingLid, ComesBackToItsKeyframesOnceUnloadedAndResumesToTheSameBits) {
  // Pressed to 0.2 s and lifted by 0.3 s: the lid goes back up with its keyframes, its offset
  // gone. A solver loaded from a state saved mid-press goes on to the same bits as one never
  // stopped (the offset, its rate and the last force are in the state).
  const auto make_model = [&] { return pressed_grain(GetParam(), 20.0 * kWeight, 0.2); };
  Model whole = make_model(), resumed = make_model();
  Solver never_stopped(whole, press_settings());
  for (int k = 0; k < 45; ++k) never_stopped.step();
  EXPECT_GT(yield_offset(whole.colliders[1], never_stopped.time()), 0.0);
  StateWriter state;
  never_stopped.save_state(state);
  Solver loaded(resumed, press_settings());
  StateReader in(state.bytes());
  loaded.load_state(in);
  for (int k = 45; k < 120; ++k) {
    never_stopped.step();
    loaded.step();
  }
  EXPECT_EQ(yield_offset(whole.colliders[1], never_stopped.time()), 0.0);
  EXPECT_EQ(collider_pose(whole.colliders[1], never_stopped.time()).translation,
            whole.colliders[1].motion.back().translation);
  EXPECT_EQ(resumed.particles.x, whole.particles.x);
  for (size_t b = 0; b < whole.rigid_bodies.size(); ++b)
    EXPECT_EQ(resumed.rigid_bodies[b].x, whole.rigid_bodies[b].x);
  EXPECT_EQ(resumed.colliders[1].yield.offset, whole.colliders[1].yield.offset);
  EXPECT_EQ(resumed.colliders[1].yield.force, whole.colliders[1].yield.force);
}

INSTANTIATE_TEST_SUITE_P(Kinds, PressingLid, ::testing::Values(BodyKind::kRigid, BodyKind::kSoft), lid_kind_name);

TEST(YieldingCollider, ValidationNamesABadLimitAxisOrSpeed) {
  Collider lid = pressing_lid(1.0, 1.0);
  EXPECT_NO_THROW(validate(lid, 2));
  for (const auto& spoil : std::vector<std::function<void(Collider&)>>{
           [](Collider& c) { c.force_limit = 0.0; }, [](Collider& c) { c.force_limit = NAN; },
           [](Collider& c) { c.yield_axis = Vec3(0, 0, 2); }, [](Collider& c) { c.yield_speed = 0.0; },
           [](Collider& c) { c.yield_speed = INFINITY; }}) {
    Collider bad = lid;
    spoil(bad);
    EXPECT_THROW(validate(bad, 2), std::invalid_argument);
  }
}

}  // namespace
}  // namespace rice::xpbd
