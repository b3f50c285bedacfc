// Paper Figure 13: japonica grains soaked at 5 °C for five soak times, rendered with the CDRF
// at each soak's water absorption (σ0 and albedo from the water-content model), side by side
// under a low sun, so that the wetter grains' wider scattering shows at the terminator.
// Writes figure13.png (labelled), figure13_render.png and .exr (the bare render),
// figure13.csv (soak, W, σ0, albedo, mean radiance of each grain's lit and shadowed halves)
// and run_info.txt.
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
  std::uint64_t seed = 1;
};

void validate(const Figure13Settings& settings);

void figure13_command(const Figure13Settings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
