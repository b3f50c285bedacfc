// Builds a scene run's world (world.hpp) from its scene: the grain variants (generated in
// parallel, each a porous grain with its simulation and render meshes and its collision
// spheres), the grains as instances of them, the colliders (the container, the scene's
// analytic ones, and its meshes as distance grids), the emitter's layout, and each grain's
// body, rigid or soft, parked and asleep until the emitter releases it.
#pragma once

#include "experiments/scene/emitter.hpp"
#include "experiments/scene/scene.hpp"
#include "experiments/scene/world.hpp"

namespace rice::experiments {

/// Throws std::invalid_argument where the emitter cannot lay out the scene.
World build_world(const Scene& scene, Emitter& emitter);

}  // namespace rice::experiments
