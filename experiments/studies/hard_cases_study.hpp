// `rice study hard-cases`: soft grains at scale where a solver is most likely to fail
// (issue 25, part 5), each a scene in experiments/scenes/cases/ run in a process of its own:
//  - bunny_pressed: the bunny mould filled, its pile pressed by a lid aimed at 80% of its
//    settled height and released; the lid gives way past its force limit (the case file's, or
//    lid_force). A first run to the press's start measures the settled top; the lid's lowest
//    pose is set from it. Checked 2 s after the release.
//  - cooker_drop: a clump dropped 10 cm onto the rice cooker's floor. Checked at the end.
// A case passes when every position and velocity is finite, no tet is inverted and the
// deepest overlap between grains is under 10% of the thinnest grain's thickness. Writes
// hard_cases.csv (a row per case, with its grains, time, peak memory and the measures) and
// run_info.txt; each case's runs are in folders of their own.
#pragma once

#include <cstdint>
#include <filesystem>

namespace rice::experiments {

struct HardCasesStudySettings {
  std::filesystem::path scenes = "experiments/scenes";  ///< the folder holding cases/
  int bunny_grains = 3600, cooker_grains = 34000;
  double fill_seconds = 3.5;  ///< the bunny's fill; it settles 0.5 s, then the lid comes down
  int cooker_frames = 90;
  double pressed_fraction = 0.8;  ///< the lid's bottom at this fraction of the settled height
  double press_seconds = 1.0;     ///< the lid's way down, from 15 cm to that bottom [s]
  /// The lid's force limit [N] (it gives way past it, collider.hpp); 0: the case file's.
  double lid_force = 0.0;
  std::uint64_t seed = 0;         ///< the grains' seed in both cases; 0: the case files' own
  double overlap_limit = 0.1;     ///< of the thickness
  int threads = 0;                ///< of each run; 0: the machine's

  /// 40 grains a case, a 1 s fill and 45 frames of drop: seconds, for CI.
  static HardCasesStudySettings quick();
};

/// Throws std::invalid_argument naming the setting out of range or the case file missing.
void validate(const HardCasesStudySettings& settings);

/// Runs the cases; returns whether all passed (each case's row says which measure failed).
bool hard_cases_study_command(const HardCasesStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
