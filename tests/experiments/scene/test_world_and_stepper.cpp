// The world builder (experiments/scene/world_builder.hpp), the world's grain operations and the
// stepper: every grain is built parked and asleep beside the colliders in their order; the
// effects a scene leaves off are off in the model, its sleep rule and soft grains' vertex mass
// floor reach it; a rigid grain's render mesh rides its pose; the stepper steps a frame with the
// scene's substeps and method.
#include <gtest/gtest.h>

#include <filesystem>

#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/spout_emitter.hpp"
#include "experiments/scene/stepper.hpp"
#include "experiments/scene/world_builder.hpp"
#include "grains/embedding.hpp"

namespace rice::experiments {
namespace {

using xpbd::Vec3;

TEST(WorldBuilder, BuildsEveryGrainParkedAndAsleepBesideTheCollidersInOrder) {
  // The shari: a plate, no analytic collider, two meshes (the mould and the lid).
  const Scene scene = read_scene_file(std::filesystem::path(RICE_SCENES_DIR) / "shari.toml",
                                      {"grains.count=6", "grains.variants=2"});
  const auto emitter = std::make_unique<SpoutEmitter>(scene.emitter, scene.container);
  World world = build_world(scene, *emitter);
  ASSERT_EQ(world.model.colliders.size(), 3u);
  EXPECT_EQ(world.model.colliders[0].shape, xpbd::ColliderShape::kHalfSpace);
  EXPECT_EQ(world.first_mesh_collider, 1);
  EXPECT_EQ(world.model.colliders[1].shape, xpbd::ColliderShape::kDistanceGrid);
  EXPECT_EQ(world.model.colliders[1].removal_time, 4.5);  // the mould
  EXPECT_EQ(world.count(), 6);
  EXPECT_EQ(world.released, 0);
  EXPECT_GT(world.grain_length, 5e-3);
  for (int g = 0; g < 6; ++g) {
    EXPECT_TRUE(world.model.bodies[g].asleep);
    EXPECT_NEAR((world.centre(g) - world.parking(g) - world.initial_centre[g]).norm(), 0.0, 1e-12);
    EXPECT_GT(world.parking(g).x(), 1.0);  // metres from everything
    EXPECT_GT(world.model.bodies[g].bond_strength, 0.0);
  }
}

/// `count` soft grains of one variant on a plate.
Scene soft_grains_on_a_plate(int count) {
  Scene scene;
  scene.container.kind = Container::kPlate;
  scene.grains.count = count;
  scene.grains.variants = 1;
  scene.grains.body = xpbd::BodyKind::kSoft;
  return scene;
}

TEST(WorldBuilder, EffectsTheSceneLeavesOffAreOffInTheModel) {
  Scene scene = soft_grains_on_a_plate(2);
  SpoutEmitter on_emitter(scene.emitter, scene.container);
  const World on = build_world(scene, on_emitter);
  EXPECT_GT(on.rayleigh_time, 0.0);
  EXPECT_TRUE(on.model.contact.cohesion);
  EXPECT_TRUE(on.model.sleep.enabled);
  scene.effects = {.static_friction = 0.0, .dynamic_friction = 0.0, .cohesion = false, .damping = false, .sleeping = false};
  SpoutEmitter off_emitter(scene.emitter, scene.container);
  const World off = build_world(scene, off_emitter);
  EXPECT_EQ(off.rayleigh_time, 0.0);
  EXPECT_FALSE(off.model.contact.cohesion);
  EXPECT_FALSE(off.model.sleep.enabled);
  EXPECT_EQ(off.model.contact.static_friction, 0.0);
  EXPECT_EQ(off.model.colliders[0].static_friction, 0.0);
  EXPECT_EQ(off.model.bodies[0].bond_strength, 0.0);
}

TEST(WorldBuilder, TheSleepRuleOfTheSceneFileReachesTheModel) {
  const auto sleep_of = [](const std::vector<std::string>& overrides) {
    const Scene scene = read_scene_file(std::filesystem::path(RICE_SCENES_DIR) / "shari.toml", overrides);
    SpoutEmitter emitter(scene.emitter, scene.container);
    return build_world(scene, emitter).model.sleep;
  };
  const xpbd::SleepSettings defaults = sleep_of({"grains.count=2", "grains.variants=1"});
  EXPECT_EQ(defaults.steps, 5);  // the scenes' default (docs/studies.md#sleep), not the solver's 15
  EXPECT_EQ(defaults.speed, 2e-3);
  const xpbd::SleepSettings set =
      sleep_of({"grains.count=2", "grains.variants=1", "effects.sleep_frames=7", "effects.sleep_speed_m_s=0.004"});
  EXPECT_EQ(set.steps, 7);
  EXPECT_EQ(set.speed, 0.004);
}

TEST(WorldBuilder, VertexBlockDescentTakesTheSoaksDampingAsStrainRateDampingUnlessAskedForThePapers) {
  Scene scene = soft_grains_on_a_plate(1);
  double tau = 0.0;
  const auto first_tet = [&] {
    SpoutEmitter emitter(scene.emitter, scene.container);
    const World world = build_world(scene, emitter);
    tau = world.rayleigh_time;
    return world.model.neo_hookean.front();
  };
  const xpbd::NeoHookeanTet xpbd_tet = first_tet();  // XPBD: the paper's Rayleigh damping of the constraints
  EXPECT_GT(tau, 0.0);
  EXPECT_GT(xpbd_tet.beta_deviatoric, 0.0);
  EXPECT_EQ(xpbd_tet.strain_rate_damping, 0.0);
  scene.solver.vertex_block_descent = true;
  const xpbd::NeoHookeanTet vbd_tet = first_tet();
  EXPECT_EQ(vbd_tet.beta_deviatoric, 0.0);
  EXPECT_EQ(vbd_tet.beta_hydrostatic, 0.0);
  EXPECT_EQ(vbd_tet.strain_rate_damping, tau);
  scene.solver.vbd_strain_rate_damping = false;
  const xpbd::NeoHookeanTet paper_tet = first_tet();
  EXPECT_EQ(paper_tet.beta_deviatoric, xpbd_tet.beta_deviatoric);
  EXPECT_EQ(paper_tet.strain_rate_damping, 0.0);
}

TEST(WorldBuilder, SoftGrainsVertexMassesHaveTheScenesFloorWithTheirMassAndCentre) {
  Scene scene = soft_grains_on_a_plate(1);
  const auto masses = [&](double floor) {
    scene.grains.vertex_mass_floor = floor;
    SpoutEmitter emitter(scene.emitter, scene.container);
    const World world = build_world(scene, emitter);
    return std::pair{Eigen::VectorXd(world.model.particles.w.cwiseInverse()), world.model.particles.x};
  };
  const auto [lumped, x] = masses(0.0);
  const auto [floored, same_x] = masses(0.5);
  EXPECT_EQ(x, same_x);
  EXPECT_LT(lumped.minCoeff(), 0.5 * lumped.mean());  // a light tip, as a coarse mesh has
  EXPECT_GE(floored.minCoeff(), 0.5 * lumped.mean() * (1.0 - 1e-9));
  EXPECT_NEAR(floored.sum(), lumped.sum(), 1e-12 * lumped.sum());
  EXPECT_LT((x.transpose() * floored - x.transpose() * lumped).norm(), 1e-12 * lumped.sum());
}

TEST(World, ARigidGrainsRenderMeshRidesItsPose) {
  Scene scene;
  scene.container.kind = Container::kPlate;
  scene.grains.count = 2;
  scene.grains.variants = 1;
  SpoutEmitter emitter(scene.emitter, scene.container);
  World world = build_world(scene, emitter);
  const grains::Grain& grain = world.variants[0].grain;
  const grains::Vertices parked = world.rest_vertices[1].rowwise() + world.parking(1).transpose();
  const grains::Vertices expected = grains::apply_embedding(grain.embedding, parked, grain.simulation.T);
  EXPECT_LT((world.render_mesh(1).V - expected).cwiseAbs().maxCoeff(), 1e-12);
  const Vec3 offset(0.0, 0.0, 0.05);
  world.release(1, offset);  // from its parking place to its build point, 5 cm up
  EXPECT_FALSE(world.model.bodies[1].asleep);
  const grains::Vertices moved = (expected.rowwise() + (offset - world.parking(1)).transpose()).eval();
  EXPECT_LT((world.render_mesh(1).V - moved).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Stepper, StepsAFrameWithTheScenesSubstepsAndMethod) {
  Scene scene;
  EXPECT_EQ(solver_settings(scene).substeps, 80);  // rigid
  scene.grains.body = xpbd::BodyKind::kSoft;
  EXPECT_EQ(solver_settings(scene).substeps, 480);  // the stable Neo-Hookean pair
  scene.grains.elasticity = xpbd::TetMaterial::kCorotated;
  EXPECT_EQ(solver_settings(scene).substeps, 160);
  scene.solver = {.fps = 60.0, .frames = 2, .substeps = 7, .iterations = 3, .vertex_block_descent = true};
  const xpbd::SolverSettings s = solver_settings(scene);
  EXPECT_EQ(s.substeps, 7);
  EXPECT_EQ(s.iterations, 3);
  EXPECT_EQ(s.time_step, 1.0 / 60.0);
  EXPECT_EQ(s.method, xpbd::Method::kVbd);

  scene.container.kind = Container::kPlate;
  scene.grains.count = 1;
  scene.grains.variants = 1;
  SpoutEmitter emitter(scene.emitter, scene.container);
  World world = build_world(scene, emitter);
  emitter.emit(world, 0.0);
  Stepper stepper(world.model, scene);
  const double height = world.centre(0).z();
  stepper.step();
  EXPECT_DOUBLE_EQ(stepper.time(), 1.0 / 60.0);
  EXPECT_LT(world.centre(0).z(), height);  // it falls
  RunInfoEntries info;
  stepper.report(info);
  EXPECT_EQ(info[2], (std::pair<std::string, std::string>{"method", "vbd"}));
}

}  // namespace
}  // namespace rice::experiments
