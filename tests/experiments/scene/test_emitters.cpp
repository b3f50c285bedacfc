// The emitters (experiments/scene/emitter.hpp): the spout's layers leave evenly over its time
// from inside its opening, and it refuses layers that would leave inside each other; the
// clump's leave at once, stacked a little over a grain length apart; the fill drops randomly
// turned grains at free points of the mould's lattice, shifted each round, for its time.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>

#include "experiments/scene/clump_emitter.hpp"
#include "experiments/scene/fill_emitter.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_run.hpp"
#include "experiments/scene/spout_emitter.hpp"
#include "experiments/scene/world_builder.hpp"

namespace rice::experiments {
namespace {

using xpbd::Vec3;

/// `count` rigid grains of one variant over a plate, from an opening 1 cm up, 12 mm in radius.
Scene plate_scene(int count) {
  Scene scene;
  scene.container.kind = Container::kPlate;
  scene.grains.count = count;
  scene.grains.variants = 1;
  scene.emitter.height = 0.01;
  scene.emitter.radius = 0.012;
  return scene;
}

/// How far grain g was moved from where it was built.
Vec3 offset(const World& world, int g) { return world.centre(g) - world.initial_centre[g]; }

TEST(SpoutEmitter, LayersLeaveEvenlyOverItsTimeFromInsideTheOpening) {
  Scene scene = plate_scene(30);
  scene.emitter.seconds = 1.0;
  SpoutEmitter spout(scene.emitter, scene.container);
  World world = build_world(scene, spout);
  const int per_layer = world.parking_row;
  ASSERT_GT(per_layer, 1);
  ASSERT_LT(per_layer, 30);
  const int layers = (30 + per_layer - 1) / per_layer;
  for (const Vec3& drop : world.drops) {
    EXPECT_LE(drop.head<2>().norm(), scene.emitter.radius + 1e-12);
    EXPECT_EQ(drop.z(), scene.emitter.height);
  }
  spout.emit(world, 0.0);
  EXPECT_EQ(world.released, per_layer);
  EXPECT_NEAR(offset(world, 0).norm(), 0.0, 1e-12);  // released where it was built
  EXPECT_FALSE(world.model.bodies[0].asleep);
  EXPECT_TRUE(world.model.bodies[per_layer].asleep);  // still parked
  spout.emit(world, 0.5 / layers);
  EXPECT_EQ(world.released, per_layer);
  const double top = world.top();
  spout.emit(world, 1.0 / layers + 1e-9);
  EXPECT_EQ(world.released, 2 * per_layer);
  // The first layer has not fallen (no step): the opening rose to 1.5 grain lengths above it.
  EXPECT_NEAR(offset(world, per_layer).z(), top + 1.5 * world.grain_length - scene.emitter.height, 1e-12);
  spout.emit(world, 1.0);
  EXPECT_EQ(world.released, 30);
}

TEST(SpoutEmitter, RefusesLayersReleasedInsideEachOther) {
  // 800 grains five a layer over 3 s: a layer every 19 ms, while a grain needs ~40 ms to fall
  // its own length. Refused before any file is written.
  Scene scene;
  scene.container.kind = Container::kPlate;
  scene.grains.variants = 1;
  scene.emitter.seconds = 3.0;
  const std::filesystem::path folder = std::filesystem::path(RICE_TEST_SCRATCH) / "refused-pour";
  std::filesystem::remove_all(folder);
  EXPECT_THROW(run_scene(scene, folder), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(folder));
}

TEST(ClumpEmitter, EveryLayerLeavesAtOnceStackedAboveTheOneBelow) {
  Scene scene = plate_scene(30);
  scene.emitter.kind = EmitterKind::kClump;
  ClumpEmitter clump(scene.emitter, scene.container);
  World world = build_world(scene, clump);
  const int per_layer = world.parking_row;
  clump.emit(world, 0.0);
  EXPECT_EQ(world.released, 30);
  for (int g = 0; g < 30; ++g) EXPECT_NEAR(offset(world, g).z(), 1.05 * world.grain_length * (g / per_layer), 1e-12);
  RunInfoEntries info;
  clump.report(world, info);
  EXPECT_EQ(info.front(), (std::pair<std::string, std::string>{"emitter", "clump"}));
}

TEST(FillEmitter, DropsRandomlyTurnedGrainsAtFreePointsOfAnotherLatticeEachRoundForItsTime) {
  // 1200 grains of one variant and the shari mould, whose lattice holds a few hundred.
  const Scene scene = read_scene_file(std::filesystem::path(RICE_SCENES_DIR) / "shari.toml",
                                      {"grains.count=1200", "grains.variants=1", "grains.body=\"rigid\""});
  FillEmitter fill(scene);
  World world = build_world(scene, fill);
  const xpbd::Collider& mould = world.model.colliders[world.first_mesh_collider + scene.emitter.mould];
  const int lattice = world.parking_row;
  ASSERT_LT(2 * lattice, 1200);
  int turned = 0;  // grains not along the axes (no half turn about an axis, nor none)
  for (int g = 0; g < lattice; ++g) {
    const Eigen::Quaterniond& R = world.instances[g].rotation;
    turned += std::abs(R.w()) + std::abs(R.x()) + std::abs(R.y()) + std::abs(R.z()) > 1.01;
  }
  EXPECT_GT(turned, 0.95 * lattice);
  // Grains that settled leave the points above them free; here every grain is lifted away.
  const auto lift_all = [&] {
    for (int g = 0; g < world.released; ++g) world.model.rigid_bodies[world.model.bodies[g].rigid_body].x.z() += 1.0;
  };
  fill.emit(world, 0.0);
  // A round fills its lattice, shifted from the one the grains were parked on: about as many
  // points (16 in the shari's mould).
  const int first = world.released;
  EXPECT_GE(first, 0.5 * lattice);
  EXPECT_LE(first, 1.5 * lattice);
  // Released in the mould's room, L apart, each off its round's lattice by at most L/20 per
  // axis: in x and y its phase φ = 4π x / cell (the same for the two layers, a half cell apart)
  // lies within 4π/22 of the lattice's, so within twice that of the round's mean phase.
  const double L = world.grain_length, cell = 1.1 * L;
  const auto phase = [&](int begin, int end, int axis) {
    std::complex<double> sum = 0.0;
    for (int g = begin; g < end; ++g) sum += std::polar(1.0, 4.0 * M_PI * world.centre(g)[axis] / cell);
    return sum / std::abs(sum);
  };
  const std::complex<double> x_phase = phase(0, first, 0), y_phase = phase(0, first, 1);
  for (int g = 0; g < first; ++g) {
    const xpbd::Vec3 c = world.centre(g);
    EXPECT_GT(xpbd::local_signed_distance(mould, c).distance, 0.4 * L) << g;
    EXPECT_LE(std::abs(std::arg(phase(g, g + 1, 0) / x_phase)), 8.0 * M_PI / 22.0 + 1e-9) << g;
    EXPECT_LE(std::abs(std::arg(phase(g, g + 1, 1) / y_phase)), 8.0 * M_PI / 22.0 + 1e-9) << g;
    EXPECT_LT(world.model.rigid_bodies[world.model.bodies[g].rigid_body].v.z(), -0.9) << g;  // dropped from a hand
    for (int h = 0; h < g; ++h) EXPECT_GE((world.centre(h) - c).norm(), L - 1e-12) << g << " " << h;
  }
  lift_all();
  fill.emit(world, 0.5 * scene.emitter.round_seconds);  // not yet the next round
  EXPECT_EQ(world.released, first);
  fill.emit(world, scene.emitter.round_seconds);
  const int second = world.released - first;
  EXPECT_GE(second, 0.5 * lattice);
  // The second round's lattice is another: with one for every round, grains dropped at its
  // points stacked in columns.
  EXPECT_GT(std::abs(std::arg(phase(first, first + second, 0) / x_phase)) +
                std::abs(std::arg(phase(first, first + second, 1) / y_phase)),
            0.5);
  lift_all();
  fill.emit(world, scene.emitter.seconds);  // the fill's time is over: no more rounds
  EXPECT_EQ(world.released, first + second);
  EXPECT_LT(scene.emitter.seconds, mould.removal_time);
  RunInfoEntries info;
  fill.report(world, info);
  EXPECT_NE(std::find(info.begin(), info.end(), std::pair<std::string, std::string>{"fill_rounds", "2"}), info.end());
}

}  // namespace
}  // namespace rice::experiments
