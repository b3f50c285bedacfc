// The renderer studies' test scene: a plate of japonica grains (from 4 generated variants,
// lying flat with random turns and shifts on a 2D grid) on a grey ground, under a sun and a
// sky, seen from 40° above. One definition, so that every study measures the same picture.
#pragma once

#include <cstdint>
#include <vector>

#include "shading/camera.hpp"
#include "shading/lights.hpp"
#include "shading/render_scene.hpp"

namespace rice::experiments {

struct GrainPlate {
  shading::RenderScene scene;  ///< grains take material 0, the ground material 1
  std::vector<int> grain_instances;
  shading::Lights lights;
  shading::Camera camera;
};

/// Builds `grains` grains from `seed` into `plate` (whose scene is committed after). The sun
/// has the given angular radius [rad] (the real sun's by default).
void build_grain_plate(GrainPlate& plate, int grains, std::uint64_t seed, float sun_angular_radius = 0.00465f);

}  // namespace rice::experiments
