// `rice table 1` (paper Table 1): the shari, chawan, onigiri and bunny scenes
// (experiments/scenes/*.toml) at the paper's grain counts and 180 frames, each run into its
// own folder, and table1.csv / table1.md side by side with the paper's times: our simulation
// time (the scene as it ships: soft grains), the same scene's with rigid grains, the paper's
// and their ratio, and how many grains the emitter placed; our render time at the scene's preview setting and, with
// `full`, at the paper's 3840 × 2160 and 800 samples per pixel; and what each scene simulates
// and renders.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rice::experiments {

struct Table1Settings {
  std::filesystem::path scenes = "experiments/scenes";  ///< the folder of shari.toml, chawan.toml, ...
  bool full = false;  ///< also render each last frame at 3840 × 2160, 800 spp (long on two cores)
  /// `--set section.key=value` for every scene (a short variant: fewer grains and frames).
  std::vector<std::string> overrides;
};

void table1_command(const Table1Settings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
