// One soft grain dropped on the ground (simulate_grain_at_rest, grain_substep_study.hpp), on
// its particles and, as in a scene, on its collision spheres: the step sizes at which XPBD
// brings it to rest, for the default mesh and a coarse one (docs/studies.md, grain-substeps).
#include <gtest/gtest.h>

#include "experiments/studies/grain_substep_study.hpp"

namespace rice::experiments {
namespace {

grains::Grain japonica(int min_vertices, int max_vertices) {
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  recipe.simulation.min_vertices = min_vertices;
  recipe.simulation.max_vertices = max_vertices;
  return grains::make_grain(recipe, 3);
}

void expect_at_rest_on_ground(const GrainRestRun& run) {
  EXPECT_TRUE(run.stable()) << "fastest particle " << run.fastest << " m/s, smallest volume ratio "
                            << run.volume_ratio;
  // It fell the 1 cm and lies on the ground, not above it nor in it by more than the
  // spheres' fit leaves a vertex outside them (0.2 mm of a 2 mm thickness).
  EXPECT_GT(run.x.col(2).minCoeff(), -3e-4);
  EXPECT_LT(run.x.col(2).minCoeff(), 1e-3);
}

TEST(GrainRest, DefaultMeshComesToRestAtTheStudysStableStepOnParticlesAndOnSpheres) {
  const grains::Grain grain = japonica(20, 60);
  for (const bool on_spheres : {false, true}) {
    SCOPED_TRACE(on_spheres ? "on spheres" : "on particles");
    const GrainRestSetup setup{.frames = 120, .drop_height = 0.01, .on_spheres = on_spheres};
    expect_at_rest_on_ground(simulate_grain_at_rest(grain, setup, xpbd::Method::kXpbd, 160, 1));
  }
}

TEST(GrainRest, CoarseMeshComesToRestAtTwiceTheStep) {
  // h = 1/(60 · 80) = 2.08e-4 s, 160 substeps per 30 fps frame: the target, met by a
  // single grain of 12 vertices (the 20-vertex default needs h = 1.04e-4 s).
  const grains::Grain grain = japonica(8, 12);
  ASSERT_LE(grain.simulation.V.rows(), 12);
  for (const bool on_spheres : {false, true}) {
    SCOPED_TRACE(on_spheres ? "on spheres" : "on particles");
    const GrainRestSetup setup{.frames = 120, .drop_height = 0.01, .on_spheres = on_spheres};
    expect_at_rest_on_ground(simulate_grain_at_rest(grain, setup, xpbd::Method::kXpbd, 80, 1));
  }
}

}  // namespace
}  // namespace rice::experiments
