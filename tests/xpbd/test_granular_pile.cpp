// Many grains: 200 rigid grains poured into a box settle (kinetic energy under 1e-9 J) with
// every penetration under 5% of a grain's thickness at rest (10% while landing), sleeping does
// not change where they settle, and the same run gives the same numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/solver.hpp"

namespace rice::xpbd {
namespace {

using namespace test_support;

constexpr double kBoxHalfWidth = 0.02;  // a 4 cm square box

/// 200 grains on a 4 × 4 lattice, 13 layers high, above a 4 cm box, each turned about the
/// vertical by its own angle and tilted a little; 7.5 mm apart, so none touch at the start.
Model poured_grains(bool sleeping) {
  Model model;
  model.contact.static_friction = 0.5;
  model.contact.dynamic_friction = 0.4;
  model.sleep.enabled = sleeping;
  add_open_box(model, kBoxHalfWidth);
  for (int k = 0; k < 200; ++k) {
        const int layer = k / 16, i = k % 4, j = (k / 4) % 4;
        const Vec3 centre(-0.01125 + 0.0075 * i, -0.01125 + 0.0075 * j, 0.004 + 0.006 * layer);
        const Vec3 corner = centre - 0.5 * Vec3(kGrainLength, kGrainWidth, kGrainThickness);
        const int b = add_grain(model, BodyKind::kRigid, corner);
        RigidBody& rigid = model.rigid_bodies[model.bodies[b].rigid_body];
        rigid.set_orientation(Quat(Eigen::AngleAxisd(0.37 * k, Vec3::UnitZ())) *
                              Quat(Eigen::AngleAxisd(0.2 * std::sin(k), Vec3::UnitX())) * rigid.q());
        rigid.remember_pose();
  }
  return model;
}

struct Settled {
  double kinetic_energy, peak_penetration, final_penetration, mean_height, top_height, seconds;
  std::vector<Vec3> centres;
};

Settled settle(bool sleeping, double max_seconds = 3.0) {
  Model model = poured_grains(sleeping);
  SolverSettings settings;
  settings.time_step = 1.0 / 100.0;
  settings.substeps = 40;  // 20 left 3e-5 m penetrations and 2e-9 J after 3 s in a 13-grain-high pile
  settings.iterations = 1;
  settings.execution = Execution::kSerial;
  Solver solver(model, settings);
  Settled s{};
  for (int step = 0; step < max_seconds * 100; ++step) {
    solver.step();
    s.final_penetration = solver.contacts()->statistics().max_penetration;
    s.peak_penetration = std::max(s.peak_penetration, s.final_penetration);
    s.kinetic_energy = kinetic_energy(model);
    s.seconds = solver.time();
    if (step > 50 && s.kinetic_energy < 1e-9) break;
  }
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    s.centres.push_back(body_centre(model, static_cast<int>(b)));
    s.mean_height += s.centres.back().z() / model.bodies.size();
    s.top_height = std::max(s.top_height, s.centres.back().z());
  }
  return s;
}

TEST(GranularPile, TwoHundredGrainsSettleWithoutInterpenetratingAsleepOrAwake) {
  const Settled awake = settle(false), asleep = settle(true);
  for (const Settled* s : {&awake, &asleep}) {
    EXPECT_LT(s->kinetic_energy, 1e-9) << "still moving after " << s->seconds << " s";
    EXPECT_LT(s->final_penetration, 0.05 * kGrainThickness);
    EXPECT_LT(s->peak_penetration, 0.1 * kGrainThickness);  // landings at up to 1 m/s
    for (const Vec3& c : s->centres) {
      EXPECT_LT(std::abs(c.x()), kBoxHalfWidth);
      EXPECT_GT(c.z(), 0.0);
    }
  }
  EXPECT_NEAR(awake.mean_height, asleep.mean_height, kGrainThickness);
  EXPECT_NEAR(awake.top_height, asleep.top_height, kGrainThickness);
  RecordProperty("peak_penetration_awake", std::to_string(awake.peak_penetration));
  RecordProperty("settle_seconds_awake", std::to_string(awake.seconds));
  RecordProperty("settle_seconds_asleep", std::to_string(asleep.seconds));
}

TEST(GranularPile, TheSameRunGivesTheSamePositions) {
  const Settled a = settle(true, 0.3), b = settle(true, 0.3);
  ASSERT_EQ(a.centres.size(), b.centres.size());
  for (size_t k = 0; k < a.centres.size(); ++k) EXPECT_EQ(a.centres[k], b.centres[k]) << "grain " << k;
}

}  // namespace
}  // namespace rice::xpbd
