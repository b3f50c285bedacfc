// The observers of a scene run (experiments/scene/observer.hpp): only those of the effects a
// scene calls for are made; a run writes a stats row and a pose file per frame, render meshes
// only when asked, and on a plate no section; every observer's measures reach run_info.txt.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "experiments/io/numeric_csv.hpp"
#include "experiments/scene/carried_observer.hpp"
#include "experiments/scene/clump_emitter.hpp"
#include "experiments/scene/impact_observer.hpp"
#include "experiments/scene/render_mesh_observer.hpp"
#include "experiments/scene/scene_parts.hpp"
#include "experiments/scene/scene_run.hpp"
#include "experiments/scene/section_observer.hpp"
#include "experiments/scene/stepper.hpp"
#include "experiments/scene/world_builder.hpp"

namespace rice::experiments {
namespace {

namespace fs = std::filesystem;

int files_with(const fs::path& folder, const std::string& extension) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(folder)) n += entry.path().extension() == extension;
  return n;
}

int lines_of(const fs::path& path) {
  std::ifstream in(path);
  return static_cast<int>(std::count(std::istreambuf_iterator<char>(in), {}, '\n'));
}

std::string text_of(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// A few grains of one variant dropped as a clump onto a plate.
Scene clump_on_a_plate(int grains, int frames) {
  Scene scene;
  scene.container.kind = Container::kPlate;
  scene.emitter.kind = EmitterKind::kClump;
  scene.grains.count = grains;
  scene.grains.variants = 1;
  scene.solver.frames = frames;
  return scene;
}

template <class Kind>
int observers_of_kind(const Scene& scene) {
  int n = 0;
  for (const auto& observer : make_observers(scene, fs::path(RICE_TEST_SCRATCH) / "unused"))
    n += dynamic_cast<const Kind*>(observer.get()) != nullptr;
  return n;
}

/// A box 10 x 10 cm and 1 cm thick, lifted from z = 0 at 0 s to z = 0.1 m at 1 s.
xpbd::Collider lifted_board() {
  xpbd::Collider board;
  board.shape = xpbd::ColliderShape::kBox;
  board.half_extents = xpbd::Vec3(0.05, 0.05, 0.005);
  board.motion = {{0.0, xpbd::Vec3::Zero(), xpbd::Quat::Identity()},
                  {1.0, xpbd::Vec3(0, 0, 0.1), xpbd::Quat::Identity()}};
  return board;
}

TEST(Observers, OnlyTheEffectsASceneCallsForAreObserved) {
  Scene scene;
  EXPECT_EQ(observers_of_kind<RenderMeshObserver>(scene), 0);
  scene.effects.render_meshes = true;
  EXPECT_EQ(observers_of_kind<RenderMeshObserver>(scene), 1);
  xpbd::Collider board = lifted_board();
  board.motion.pop_back();  // one keyframe: it stands still and carries nothing
  scene.colliders.push_back(board);
  scene.collider_materials.push_back("wood");
  EXPECT_EQ(observers_of_kind<CarriedObserver>(scene), 0);
  scene.colliders.push_back(lifted_board());
  scene.collider_materials.push_back("wood");
  EXPECT_EQ(observers_of_kind<CarriedObserver>(scene), 1);
}

TEST(CarriedObserver, CountsTheGrainsOverAnUpFacingFaceOfAMovingColliderOnce) {
  // At 1 s the board's top face is at z = 0.105 m; the reach is 1 cm.
  const std::vector<xpbd::Vec3> centres = {
      {0.0, 0.0, 0.107},   // on it
      {0.04, 0.04, 0.112},  // on it, a layer up
      {0.0, 0.0, 0.093},   // under it: its face there looks down
      {0.2, 0.0, 0.107},   // beside it, out of reach
      {0.0, 0.0, 0.125},   // over it, out of reach
      {0.0, 0.0, 0.007}};  // on the floor it left
  std::vector<xpbd::Collider> colliders = {lifted_board()};
  EXPECT_EQ(carried_grains(colliders, centres, 1.0, 0.01), 2);
  EXPECT_EQ(carried_grains(colliders, centres, 0.0, 0.01), 1);  // at the start it lay on the floor
  colliders.push_back(lifted_board());  // two boards in one place: each grain counted once
  EXPECT_EQ(carried_grains(colliders, centres, 1.0, 0.01), 2);
  for (xpbd::Collider& board : colliders) board.removal_time = 0.5;  // gone: carries nothing
  EXPECT_EQ(carried_grains(colliders, centres, 1.0, 0.01), 0);
  colliders = {lifted_board()};
  colliders.front().motion.pop_back();  // standing still, a grain on it is not carried
  EXPECT_EQ(carried_grains(colliders, centres, 1.0, 0.01), 0);
}

TEST(Observers, AMouldsRoomCountsItsGrainsInItsLastPoseBeforeItGoes) {
  // Turned over from 1 s to 2 s and taken away at 3 s, as the bunny's mould is: its grains are
  // in the turned room (in its pose at time 0 none of them were).
  xpbd::Collider mould;
  mould.motion = {{0.0, xpbd::Vec3(0, 0, 0.06), xpbd::Quat::Identity()},
                  {1.0, xpbd::Vec3(0, 0, 0.06), xpbd::Quat::Identity()},
                  {2.0, xpbd::Vec3(0, 0, 0.05), xpbd::Quat(Eigen::AngleAxisd(M_PI, xpbd::Vec3::UnitX()))}};
  mould.removal_time = 3.0;
  EXPECT_EQ(room_pose(mould).translation, xpbd::Vec3(0, 0, 0.05));
  EXPECT_NEAR(room_pose(mould).rotation.angularDistance(mould.motion.back().rotation), 0.0, 1e-12);
  mould.removal_time = 1.5;  // taken away half way through the turn
  EXPECT_NEAR(room_pose(mould).translation.z(), 0.055, 1e-12);
  mould.removal_time = INFINITY;  // never taken away: where its keyframes leave it
  EXPECT_EQ(room_pose(mould).translation, xpbd::Vec3(0, 0, 0.05));
}

TEST(Observers, ARunWritesAStatsRowAndAPoseFilePerFrameAndItsMeasures) {
  Scene scene = clump_on_a_plate(6, 4);
  const fs::path plain = fs::path(RICE_TEST_SCRATCH) / "observers-plain";
  fs::remove_all(plain);
  const SceneResult result = run_scene(scene, plain);
  EXPECT_EQ(lines_of(plain / "stats.csv"), 1 + 4);
  EXPECT_EQ(files_with(plain / "frames", ".csv"), 4);
  EXPECT_EQ(files_with(plain / "frames", ".ply"), 0);
  EXPECT_EQ(lines_of(plain / "final_centres.csv"), 1 + 6);
  EXPECT_EQ(lines_of(plain / "grains.csv"), 1 + 6);
  EXPECT_FALSE(fs::exists(plain / "section.png"));
  EXPECT_FALSE(fs::exists(plain / "chawan.obj"));
  EXPECT_FALSE(fs::exists(plain / "yield.csv"));  // no collider gives way
  EXPECT_EQ(result.in_container, -1);
  EXPECT_GT(result.simulation_seconds, 0.0);
  const std::string info = text_of(plain / "run_info.txt");
  for (const char* line : {"emitter: clump\n", "grains_in_container: n/a\n", "substeps: 80\n", "clusters: ",
                           "awake_at_end: ", "wall_s: "})
    EXPECT_NE(info.find(line), std::string::npos) << line;

  scene.effects.render_meshes = true;
  const fs::path meshes = fs::path(RICE_TEST_SCRATCH) / "observers-meshes";
  fs::remove_all(meshes);
  run_scene(scene, meshes);
  EXPECT_EQ(files_with(meshes / "frames", ".ply"), 4);

  // A collider that gives way past a force: a row a frame in yield.csv.
  scene.effects.render_meshes = false;
  xpbd::Collider lid;
  lid.shape = xpbd::ColliderShape::kBox;
  lid.half_extents = xpbd::Vec3(0.02, 0.02, 0.005);
  lid.motion.front().translation = xpbd::Vec3(0.0, 0.0, 0.2);
  lid.force_limit = 1.0;
  scene.colliders.push_back(lid);
  scene.collider_materials.push_back("wood");
  const fs::path yielding = fs::path(RICE_TEST_SCRATCH) / "observers-yield";
  fs::remove_all(yielding);
  run_scene(scene, yielding);
  EXPECT_EQ(lines_of(yielding / "yield.csv"), 1 + 4);
}

TEST(Observers, StatsGiveEachFramesInvertedTetsAndSmallestVolumeRatioOfSoftGrains) {
  Scene scene = clump_on_a_plate(2, 3);
  const fs::path rigid = fs::path(RICE_TEST_SCRATCH) / "observers-tets-rigid";
  fs::remove_all(rigid);
  run_scene(scene, rigid);
  const NumericCsv rigid_stats = read_numeric_csv(rigid / "stats.csv");
  for (const std::vector<double>& row : rigid_stats.rows) {
    EXPECT_EQ(row[rigid_stats.column("inverted_tets")], 0.0);
    EXPECT_TRUE(std::isnan(row[rigid_stats.column("smallest_volume_ratio")]));  // no tets
  }
  EXPECT_EQ(text_of(rigid / "run_info.txt").find("smallest_volume_ratio_over_frames"), std::string::npos);

  scene.grains.body = xpbd::BodyKind::kSoft;
  const fs::path soft = fs::path(RICE_TEST_SCRATCH) / "observers-tets-soft";
  fs::remove_all(soft);
  run_scene(scene, soft);
  const NumericCsv stats = read_numeric_csv(soft / "stats.csv");
  ASSERT_EQ(stats.rows.size(), 3u);
  double smallest = INFINITY;
  for (const std::vector<double>& row : stats.rows) {  // two grains falling and landing: near their rest volume
    EXPECT_EQ(row[stats.column("inverted_tets")], 0.0);
    EXPECT_NEAR(row[stats.column("smallest_volume_ratio")], 1.0, 0.2);
    smallest = std::min(smallest, row[stats.column("smallest_volume_ratio")]);
  }
  const std::string info = text_of(soft / "run_info.txt");
  EXPECT_NE(info.find("inverted_tets_most_in_a_frame: 0\n"), std::string::npos);
  const std::string key = "smallest_volume_ratio_over_frames: ";
  ASSERT_NE(info.find(key), std::string::npos);
  EXPECT_EQ(std::stod(info.substr(info.find(key) + key.size())), smallest);  // the column's least
}

TEST(ImpactObserver, WatchesAClumpFromTheStartAndACupFromItsRemovalAndNothingElse) {
  Scene scene;
  scene.emitter.kind = EmitterKind::kClump;
  EXPECT_EQ(drop_time(scene), 0.0);
  scene.emitter.kind = EmitterKind::kSpout;
  EXPECT_EQ(drop_time(scene), std::nullopt);
  scene.emitter.kind = EmitterKind::kFill;
  scene.emitter.mould = 0;
  scene.mesh_colliders.resize(1);
  scene.mesh_colliders[0].mesh.V = grains::Vertices{{-0.01, -0.01, -0.01}, {0.01, 0.01, 0.01}};  // 2 cm across
  xpbd::Collider& mould = scene.mesh_colliders[0].collider;
  EXPECT_EQ(drop_time(scene), std::nullopt);  // a mould never taken away
  mould.removal_time = 2.0;
  mould.motion.front().translation.z() = 0.01;
  EXPECT_EQ(drop_time(scene), std::nullopt);  // on the ground (shari, the bunny): the grains stay
  mould.motion.front().translation.z() = 0.04;
  EXPECT_EQ(drop_time(scene), 2.0);  // a cup 3 cm up
  mould.motion = {mould.motion.front(), {1.0, xpbd::Vec3(0.0, 0.0, 0.01), xpbd::Quat::Identity()}};
  EXPECT_EQ(drop_time(scene), std::nullopt);  // set down before it goes
}

TEST(ImpactObserver, MeasuresTheRiseAboveTheLowestPointAndTheLargestPrincipalStrain) {
  Scene scene;
  scene.container.kind = Container::kPlate;
  scene.emitter.kind = EmitterKind::kClump;
  scene.grains.body = xpbd::BodyKind::kSoft;
  scene.grains.count = 2;
  scene.grains.variants = 1;
  ClumpEmitter clump(scene.emitter, scene.container);
  World world = build_world(scene, clump);
  clump.emit(world, 0.0);
  const Stepper stepper(world.model, scene);
  ImpactObserver impact(0.0);
  impact.begin(world);
  // Grain 0 falls 3 mm, rises 0.5 mm, falls 1 mm more and rises 0.2 mm: its rebound is 0.5 mm.
  // Grain 1 only falls. Then grain 0 is stretched by 2% in every direction: σ_i = 1.02, while
  // grain 1 stays at rest, so the volume-weighted mean strain is 2% of grain 0's share.
  const xpbd::Body& body = world.model.bodies[0];
  auto particles = [&](int g) {
    const xpbd::Body& b = world.model.bodies[g];
    return world.model.particles.x.middleRows(b.first_particle, b.particle_count);
  };
  int frame = 0;
  for (const double dz : {-3e-3, 0.5e-3, -1.5e-3, 0.2e-3}) {
    particles(0).col(2).array() += dz;
    particles(1).col(2).array() -= 1e-3;
    impact.observe(world, stepper, ++frame, 0.0);
  }
  const xpbd::Vec3 c = world.centre(0);
  particles(0) = ((particles(0).rowwise() - c.transpose()) * 1.02).rowwise() + c.transpose();
  impact.observe(world, stepper, ++frame, 0.0);
  SceneReport report;
  impact.end(world, stepper, report);
  EXPECT_NEAR(report.result.rebound_height, 0.5 * 0.5e-3, 1e-12);  // the mean of 0.5 mm and 0
  double volume[2] = {0.0, 0.0};
  for (const xpbd::NeoHookeanTet& tet : world.model.neo_hookean)
    volume[tet.particles[0] >= body.first_particle + body.particle_count] += tet.rest_volume;
  EXPECT_NEAR(report.result.peak_strain, 0.02 * volume[0] / (volume[0] + volume[1]), 1e-9);
  EXPECT_NE(std::find(report.info.begin(), report.info.end(),
                      std::pair<std::string, std::string>{"peak_principal_strain_frame", "5"}),
            report.info.end());
  // Watching from 1 s, it sees nothing of the stretched grain at t = 0.
  ImpactObserver later(1.0);
  later.begin(world);
  later.observe(world, stepper, 1, 0.0);
  SceneReport before_the_drop;
  later.end(world, stepper, before_the_drop);
  EXPECT_EQ(before_the_drop.result.peak_strain, 0.0);
}

}  // namespace
}  // namespace rice::experiments
