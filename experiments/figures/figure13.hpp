// Paper Figure 13: japonica grains soaked at 5 °C for five soak times, rendered with the CDRF
// at each soak's water absorption (σ0 and albedo from the water-content model), side by side
// under a high sun behind them, so that the wetter grains' wider scattering shows at the
// terminator; the same row with the random-walk bake (each grain's subsurface light baked by
// photons in its own medium, shading/subsurface_bake.hpp); and path-traced, the reference
// (shading/path_tracer.hpp: light through and between the grains).
// Writes figure13.png (the three rows, labelled), figure13_render.{png,exr} (CDRF),
// figure13_reference.{png,exr} (the bake), figure13_path.{png,exr}, figure13.csv (per grain:
// soak, W, σ0, albedo, mean radiance of its lit and shaded sides in each row, the CDRF's RMS
// difference from the bake and from the path tracer) and run_info.txt (times, and the CIELAB
// ΔE*ab between the driest and the wettest grain's lit and shaded sides as displayed, per row).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rice::experiments {

struct Figure13Settings {
  std::vector<double> soak_minutes = {15, 30, 60, 120, 240};
  double temperature_c = 5.0;
  int width = 1000, height = 250;
  int samples_per_pixel = 64;
  long long photons = 300'000;  ///< the bake: per grain, per light
  int path_spp = 256;           ///< the path-traced row's samples per pixel
  std::uint64_t seed = 1;
};

void validate(const Figure13Settings& settings);

void figure13_command(const Figure13Settings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
