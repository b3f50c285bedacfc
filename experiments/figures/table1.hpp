// `rice table 1` (paper Table 1): the shari, chawan, onigiri and bunny scenes
// (experiments/scenes/*.toml) at the paper's grain counts and 180 frames, each run three times
// into its own folders: as it ships (soft grains by XPBD), by vertex block descent, and with
// rigid grains. table1.csv / table1.md set the simulation times side by side with the paper's
// and their ratio; the render time at the scene's preview setting and, with `full`, at the
// paper's 3840 × 2160 and 800 samples per pixel; and what each scene simulates and renders.
// table1_runs.csv says how each run ended: grains placed and awake, the shape's top before
// and after the mould goes, packing and the deepest overlap.
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
