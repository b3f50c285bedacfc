// `rice study sleep`: what the sleep rule's two knobs save in time and cost in accuracy
// (xpbd::SleepSettings: a grain sleeps once every point of it moved slower than `speed` over
// each of `frames` frames in a row). A scene (default: the rice cooker's fill and settling,
// 1000 soft grains, the 105 frames before its paddle comes) runs once with sleeping off, the
// reference, then once per setting: each count of frames at the scene's speed, each speed at
// the scene's frames. Grain by grain two runs part (a pile is chaotic), so a run's error is
// how far its settled pile's shape is from the reference's: the 1-Wasserstein distance between
// the grains' centre heights, and between their distances from the scene's axis. The
// reference's twin, run with one substep more a frame and no sleep, gives the noise floor: a
// setting whose error is under it is as good as the reference.
// Writes sleep.csv (a row per run: the reference, its twin, then the settings), sleep.png (the
// height error against wall time) and run_info.txt; each run's folder holds its scene run.
#pragma once

#include <filesystem>
#include <vector>

namespace rice::experiments {

struct SleepStudySettings {
  std::filesystem::path scene = "experiments/scenes/rice_cooker.toml";
  int count = 1000;
  int frames = 105;
  std::vector<int> sleep_frames{3, 5, 8, 15, 30};
  std::vector<double> sleep_speeds{1e-3, 2e-3, 4e-3};  ///< [m/s]
  int threads = 0;  ///< of each run; 0: the machine's

  /// 40 grains for 30 frames, two settings, for CI (seconds).
  static SleepStudySettings quick();
};

/// Throws std::invalid_argument naming the setting out of range.
void validate(const SleepStudySettings& settings);

/// The 1-Wasserstein distance between two samples' distributions, ∫|F_a⁻¹(u) − F_b⁻¹(u)| du,
/// over max(#a, #b) quantiles (the mean |a_(i) − b_(i)| of the sorted values when #a = #b).
double wasserstein_1(std::vector<double> a, std::vector<double> b);

void sleep_study_command(const SleepStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
