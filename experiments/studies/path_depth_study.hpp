// `rice study path-depth`: how deep the reference path tracer (shading/path_tracer.hpp) must
// follow light, and how far the fast models sit from it (issue 24, part 1).
//
// Scene: the renderer studies' plate of grains (experiments/render/grain_plate.hpp) at W = 20%,
// the grains' medium from the water-content model, under a sky and a sun of `sun_radius`
// (the real sun's by default, as the render study's).
//  - Depth: the plate path-traced at each of `depths` surface events, with the same samples and
//    seed as the reference (depth `reference_depth`), so that the difference is the truncation
//    alone; the depth chosen is the smallest within 1% RMS of the mean radiance. And the
//    reference's own noise, from a second seed.
//  - The paper's CDRF (the direct-light renderer, shading/renderer.hpp) against the reference.
// Writes path_depth.csv (method, knob, seconds, rmse, relative_rmse), path_depth.png (error
// against time, log–log), the reference image (PNG and EXR), the CDRF image and run_info.txt.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rice::experiments {

struct PathDepthSettings {
  int width = 160, height = 120;
  int grains = 48;
  int samples_per_pixel = 256;  ///< of every path-traced image
  std::vector<int> depths = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32};
  int reference_depth = 64;
  int cdrf_spp = 256;
  double sun_radius = 0.00465;  ///< [rad]
  std::uint64_t seed = 1;

  /// A small image, few samples and depths, for CI (seconds).
  static PathDepthSettings quick();
};

/// Throws std::invalid_argument naming the setting out of range.
void validate(const PathDepthSettings& settings);

void path_depth_study_command(const PathDepthSettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
