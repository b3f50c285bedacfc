// `rice study scale`: how a run's cost and memory grow with its grains (issue 25, part 3).
// For each body (rigid, soft) and grain count, a clump of that many grains (drop.toml: a block
// about as tall as it is wide, 3 cm above the plate; its radius grows as the cube root of the
// count, so the block keeps its shape) drops onto the plate and is simulated for `frames`
// frames, every grain in the scene from the first. Each run is its own `rice run --no-render` process, so its peak
// resident memory is its own. From its run_info.txt and stats.csv:
//  - the wall time per grain-frame, split into broad phase, narrow phase, solves and sleeping;
//  - the peak resident memory, and per grain the growth over the smallest run's;
//  - contacts per grain (the mean over the frames) and grains awake at the end.
// Writes scale.csv (a row per run), scale.png (time per grain-frame against grains, log–log)
// and run_info.txt; each run's folder holds its scene run.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rice::experiments {

struct ScaleStudySettings {
  std::filesystem::path scene = "experiments/scenes/drop.toml";
  std::vector<int> counts{100, 300, 1000, 3000, 10000, 34000};
  std::vector<std::string> bodies{"rigid", "soft"};
  int frames = 60;
  int threads = 0;  ///< of each run; 0: the machine's

  /// Two small counts and 10 frames, for CI (seconds).
  static ScaleStudySettings quick();
};

/// Throws std::invalid_argument naming the setting out of range.
void validate(const ScaleStudySettings& settings);

/// [m] The clump's radius for `count` grains: 20 mm for 100 (drop.toml's), growing as ∛count.
double clump_radius(int count);

void scale_study_command(const ScaleStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
