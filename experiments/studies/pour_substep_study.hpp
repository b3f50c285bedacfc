// `rice study pour-substeps`: what a pour's accuracy costs in time. A scene (scene_run.hpp; by default 800
// rigid grains poured into a 12 cm chawan) is run at several substep counts; for each, the wall time against the
// deepest overlap of two grains and of a grain into its container when the run ends.
#pragma once

#include <filesystem>
#include <vector>

#include "experiments/scene/scene.hpp"

namespace rice::experiments {

struct PourSubstepStudySettings {
  Scene scene;  ///< its substeps are replaced by each of `substeps`
  std::vector<int> substeps{20, 40, 80, 160};
};

/// Throws std::invalid_argument naming the setting and its range.
void validate(const PourSubstepStudySettings& settings);

/// Runs the pour once per substep count into folder/substeps_N, then writes
/// pour_substeps.csv, pour_substeps.png and run_info.txt.
void pour_substep_study_command(const PourSubstepStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
