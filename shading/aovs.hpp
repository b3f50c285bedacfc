// Arbitrary output variables (AOVs) of a render, beside its beauty image: per pixel, what the
// camera ray through the pixel's centre (and the lens's centre) meets first — the shading
// normal, the depth along the view axis, the material's albedo and the instance's label (a
// grain's id). For compositing, masks per grain, and denoisers that take albedo and normal.
// One ray a pixel, without anti-aliasing: an edge pixel holds one surface's values, never a
// blend of two grains' ids. The same for every integrator, and cheap beside any of them.
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "shading/camera.hpp"
#include "shading/image_tiles.hpp"
#include "shading/material.hpp"
#include "shading/render_scene.hpp"

namespace rice::shading {

struct Aovs {
  int width = 0, height = 0;           ///< of the window rendered
  std::vector<Eigen::Vector3f> normal;  ///< world-space unit shading normal; 0 where nothing is hit
  std::vector<float> depth;             ///< distance along the view axis [m]; +∞ where nothing is hit
  std::vector<Color> albedo;            ///< the material's; 0 where nothing is hit
  std::vector<float> label;             ///< the instance's label (RenderScene::add_instance); −1 where nothing is hit
};

/// The AOVs of `window` of a width × height image (empty: all of it), row-major from its
/// top-left pixel. Throws std::invalid_argument for a window outside the image or an
/// instance's material outside `materials`.
Aovs render_aovs(const RenderScene& scene, const std::vector<Material>& materials, const Camera& camera, int width,
                 int height, const PixelWindow& window = {});

}  // namespace rice::shading
