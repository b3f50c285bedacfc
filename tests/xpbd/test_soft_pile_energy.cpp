// A closed resting pile of 100 soft, cohesive grains with friction, by vertex block descent at
// one substep per 1/60 s step and 10 sweeps: every interaction is a term of the particles'
// steps (particle_contacts.hpp), so once the pile first comes to rest (a 0.5 s window's mean
// kinetic energy at round-off, under 1e-12 J: a grain of 46 mg at 0.2 µm/s) it never rises
// again, and by 10 s every grain sleeps. (With bonds and friction projected after each sweep,
// a pile gained 0.24 J over 90 frames, and a 100-grain soft pour into the chawan went
// non-finite at frame 52; with the bonds' springs at 1/α = 1e4 N/m, stiffer than the sweeps
// resolve, the pile stayed at 1e-9–1e-8 J with 90 grains awake at 10 s.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/solver.hpp"

namespace rice::xpbd {
namespace {

using namespace test_support;

constexpr double kClosedBoxHalfWidth = 0.015;  // a 3 cm square box

/// 100 soft grains on a 4 × 4 lattice, 7 layers, 7.5 mm apart, over a closed box; bonds of
/// 15 grain weights (japonica's stickiness), μ_s = 0.5 and μ_k = 0.4 between grains.
Model sticky_soft_grains() {
  Model model;
  model.contact.static_friction = 0.5;
  model.contact.dynamic_friction = 0.4;
  model.contact.cohesion = true;
  model.sleep.enabled = true;
  add_open_box(model, kClosedBoxHalfWidth);
  const double weight = kGrainDensity * kGrainLength * kGrainWidth * kGrainThickness * 9.81;
  for (int k = 0; k < 100; ++k) {
    const int layer = k / 16, i = k % 4, j = (k / 4) % 4;
    const Vec3 centre(-0.01125 + 0.0075 * i, -0.01125 + 0.0075 * j, 0.003 + 0.004 * layer);
    const int b = add_grain(model, BodyKind::kSoft, centre - 0.5 * Vec3(kGrainLength, kGrainWidth, kGrainThickness));
    model.bodies[b].bond_strength = 15.0 * weight;
  }
  return model;
}

TEST(SoftPileEnergy, ARestingStickyPileNeverGainsEnergyAndFallsAsleep) {
  Model model = sticky_soft_grains();
  const double fps = 60.0;
  Solver solver(model, {.time_step = 1.0 / fps, .substeps = 1, .iterations = 10, .method = Method::kVbd,
                        .execution = Execution::kSerial});
  const int window = static_cast<int>(fps / 2);  // 0.5 s
  std::vector<double> means;
  double sum = 0.0;
  for (int step = 0; step < 10 * fps; ++step) {
    solver.step();
    sum += kinetic_energy(model);
    if ((step + 1) % window == 0) {
      means.push_back(sum / window);
      sum = 0.0;
    }
  }
  size_t rest = 0;
  while (rest < means.size() && means[rest] > 1e-12) ++rest;
  ASSERT_LT(rest, means.size() - 2) << "never came to rest";
  for (size_t w = rest + 1; w < means.size(); ++w)
    EXPECT_LE(means[w], means[w - 1] + 1e-15) << "window " << w << " (" << 0.5 * w << " s)";
  int awake = 0;
  for (const Body& body : model.bodies) awake += !body.asleep;
  EXPECT_EQ(awake, 0);
  RecordProperty("awake", awake);
  std::string trace;
  for (const double m : means) {
    char cell[32];
    std::snprintf(cell, sizeof cell, "%.3g ", m);
    trace += cell;
  }
  RecordProperty("kinetic_energy_windows", trace);
  RecordProperty("rest_window", static_cast<int>(rest));
  RecordProperty("bonds", solver.contacts()->statistics().bonds);
}

}  // namespace
}  // namespace rice::xpbd
