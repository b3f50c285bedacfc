// Paper Figure 13: japonica grains soaked at 5 °C for five soak times, side by side under a
// high sun behind them, in three rows: the paper's CDRF at each soak's water absorption (σ0
// and albedo from the water-content model), so that the wetter grains' wider scattering shows
// at the terminator; the translucent model (the CDRF and the light through the grain,
// shading/translucency.hpp) with its bounces between grains; and path-traced, the reference
// (shading/path_tracer.hpp: light through and between the grains, each grain its medium).
// Writes figure13.png (the three rows, labelled), figure13_<row>.{png,exr} for the rows cdrf,
// translucent and path, figure13.csv (per grain: soak, W, σ0, albedo, and per row the mean
// radiance of its lit and shaded sides and its RMS difference from the reference) and
// run_info.txt (per row: time, the worst per-grain RMS, and the CIELAB ΔE*ab between the
// driest and the wettest grain's lit and shaded sides as displayed).
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
  int path_spp = 256;           ///< the path-traced row's samples per pixel
  int translucent_bounces = 1;  ///< of the translucent row
  std::uint64_t seed = 1;
};

void validate(const Figure13Settings& settings);

void figure13_command(const Figure13Settings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
