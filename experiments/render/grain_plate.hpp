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

/// The 4 japonica variants every study scene draws its grains from, as prototypes of `scene`.
struct GrainVariants {
  std::vector<int> prototypes;
  std::vector<shading::MeshVertices> meshes;  ///< their render meshes' vertices
  double length = 0.0;                        ///< the longest variant's extent [m]
};
GrainVariants add_grain_variants(shading::RenderScene& scene, std::uint64_t seed);

/// The studies' sun (of the given angular radius [rad]) and sky.
shading::Lights study_lights(float sun_angular_radius = 0.00465f);

/// Builds `grains` grains from `seed` into `plate` (whose scene is committed after). The sun
/// has the given angular radius [rad] (the real sun's by default).
void build_grain_plate(GrainPlate& plate, int grains, std::uint64_t seed, float sun_angular_radius = 0.00465f);

}  // namespace rice::experiments
