// The renderer: for each pixel, samples per pixel from a PixelSampler through the camera;
// at the first surface, direct light from every sun and area light (one sample each, shadow
// rays when shadows are on), the environment (one sample over the sphere, tested for
// occlusion when ambient occlusion is on) and, for specular materials, one sample of the
// specular lobe against the environment; rays that leave the scene see the environment.
// There is no indirect bounce: the CDRF is the paper's local shading model. A rice grain's
// shadow and occlusion rays ignore the grain itself: the CDRF's light past the terminator
// reaches the point through the grain. Tiles of 16×16 pixels (image_tiles.hpp) run on TBB's threads; the image depends only on
// the seed, never on the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "shading/adaptive_sampling.hpp"
#include "shading/camera.hpp"
#include "shading/cdrf.hpp"
#include "shading/image.hpp"
#include "shading/image_tiles.hpp"
#include "shading/lights.hpp"
#include "shading/material.hpp"
#include "shading/render_scene.hpp"
#include "shading/sampler.hpp"

namespace rice::shading {

struct RenderSettings {
  int width = 640, height = 480;
  int samples_per_pixel = 16;
  SamplerKind sampler = SamplerKind::kSobol;
  std::uint64_t seed = 1;
  bool shadows = true;
  bool ambient_occlusion = true;  ///< environment light is blocked by geometry
  PixelWindow crop{};  ///< render only these pixels, into an image of the crop's size (empty: all)
  AdaptiveSampling adaptive{};  ///< off: every pixel takes samples_per_pixel (adaptive_sampling.hpp)
};

/// Counters of one render.
struct RenderStats {
  long long camera_rays = 0, shadow_rays = 0;
  double seconds = 0.0;
};

/// The image's tiles (image_tiles.hpp), the unit of work and of progress.
inline int tile_count(const RenderSettings& s) {
  return tile_count(rendered_pixels(s.width, s.height, s.crop, "render"));
}

/// `progress(done, total)` is called after each tile, from the thread that rendered it; once
/// `cancelled()` returns true no further tile starts (the image is then incomplete).
/// Throws std::invalid_argument for sizes or sample counts below 1, or an instance whose
/// material index is outside `materials`.
Image render(const RenderScene& scene, const std::vector<Material>& materials, const Lights& lights,
             const Camera& camera, const CdrfTable& cdrf, const RenderSettings& settings,
             RenderStats* stats = nullptr, const std::function<void(int done, int total)>& progress = {},
             const std::function<bool()>& cancelled = {});

}  // namespace rice::shading
