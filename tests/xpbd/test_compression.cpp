// Stability under load (issue 10): 500 soft grains settled in a box are pressed by a moving
// plate to 60% of their free height, held, and released. Every position stays finite, no tet
// is left inverted once the plate has retreated, and no grain ends inside another.
//
// Measured (Release, 10 s): the grains' top reaches 63% of the free height (the plate's
// contacts give 0.8 mm under 13 layers); a few tets invert under the load and all recover;
// after the retreat two grains' spheres still overlap by 0.49 mm (a quarter of a grain's
// thickness), and that overlap persists over 100 ms more: it is bounded here by half the
// thickness, which catches grains pushed through each other, and is an open defect against
// the 5% of the settling test. Two Gauss–Seidel sweeps a substep are needed: with one, the
// overlap was 0.78 mm with the centres side by side; with soft spheres of rest radius (before
// sphere_radius), 1.9 mm and an inverted tet left.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/penetration.hpp"
#include "xpbd/solver.hpp"
#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {
namespace {

using namespace test_support;

constexpr double kHalfWidth = 0.018;  // a 3.6 cm square box

/// 500 soft grains, 40 a layer (4 along x, 10 along y) in 13 layers 2.5 mm apart, each turned
/// a little about the vertical so the layers do not stack in columns.
Model boxed_grains() {
  Model model;
  model.contact.static_friction = 0.5;
  model.contact.dynamic_friction = 0.4;
  add_open_box(model, kHalfWidth);
  for (int k = 0; k < 500; ++k) {
    const int layer = k / 40, i = k % 4, j = (k / 4) % 10;
    const Vec3 corner(-0.0165 + 0.0085 * i + 4e-4 * (layer % 2), -0.0175 + 0.0035 * j, 2e-4 + 0.0025 * layer);
    const int b = add_grain(model, BodyKind::kSoft, corner);
    // A turn of up to ±3° about the grain's centre, different for every grain.
    const Vec3 centre = corner + 0.5 * Vec3(kGrainLength, kGrainWidth, kGrainThickness);
    const Mat3 turn = Eigen::AngleAxisd(0.05 * std::sin(1.7 * k), Vec3::UnitZ()).toRotationMatrix();
    const Body& body = model.bodies[b];
    auto x = model.particles.x.middleRows(body.first_particle, body.particle_count);
    x = ((x.rowwise() - centre.transpose()) * turn.transpose()).rowwise() + centre.transpose();
  }
  return model;
}

double top_of_grains(const Model& model) {
  double top = -INFINITY;
  for (const Body& body : model.bodies)
    for (int s = 0; s < body.sphere_count(); ++s)
      top = std::max(top, sphere_centre(model, body, s).z() + sphere_radius(model, body, s));
  return top;
}

double smallest_tet_volume(const Model& model) {
  double smallest = INFINITY;
  for (const NeoHookeanTet& t : model.neo_hookean) {
    Vec12 x;
    for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = model.particles.x.row(t.particles[k]).transpose();
    smallest = std::min(smallest, signed_volume(x));
  }
  return smallest;
}

TEST(Compression, FiveHundredSoftGrainsPressedTo60PercentRecoverWithoutInversionOrInterpenetration) {
  Model model = boxed_grains();
  // The plate: solid above its plane (normal −z), parked 1 m up while the grains settle.
  model.colliders.push_back(half_space(-Vec3::UnitZ(), -1.0, 0.5, 0.4));
  SolverSettings settings;
  settings.time_step = 1.0 / 300.0;
  settings.substeps = 23;  // h = 1.45e-4 s, under the Neo-Hookean pair's limit (README "Known limits")
  settings.iterations = 2;  // one left grains inside each other (see above)
  Solver solver(model, settings);
  for (int step = 0; step < 15; ++step) solver.step();  // 0.05 s: the layers settle
  const double free_height = top_of_grains(model);
  ASSERT_GT(free_height, 0.02);

  // From the top down to 60% in 40 ms, held for 10 ms, back up in 40 ms, then 30 ms free.
  const double t0 = solver.time();
  const auto at = [&](double t, double height) {
    ColliderKeyframe key = model.colliders.back().motion[0];
    key.time = t;
    key.translation = Vec3(0.0, 0.0, height);
    return key;
  };
  model.colliders.back().motion = {at(t0, free_height), at(t0 + 0.04, 0.6 * free_height),
                                   at(t0 + 0.05, 0.6 * free_height), at(t0 + 0.09, 1.2 * free_height)};
  double lowest_top = INFINITY, smallest_volume_under_load = INFINITY;
  while (solver.time() < t0 + 0.12) {
    solver.step();
    ASSERT_TRUE(model.particles.x.allFinite()) << "at t = " << solver.time();
    lowest_top = std::min(lowest_top, top_of_grains(model));
    smallest_volume_under_load = std::min(smallest_volume_under_load, smallest_tet_volume(model));
  }
  EXPECT_LT(lowest_top, 0.65 * free_height);  // the plate, at 60%, did press the grains
  EXPECT_GT(smallest_tet_volume(model), 0.0);
  EXPECT_LT(deepest_penetration(model, solver.time()).between_bodies, 0.5 * kGrainThickness);
  RecordProperty("free_height_m", std::to_string(free_height));
  RecordProperty("lowest_top_over_free_height", std::to_string(lowest_top / free_height));
  RecordProperty("smallest_tet_volume_under_load_m3", smallest_volume_under_load);
  RecordProperty("deepest_overlap_after_m", deepest_penetration(model, solver.time()).between_bodies);
}

}  // namespace
}  // namespace rice::xpbd
