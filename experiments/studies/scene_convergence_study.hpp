// `rice study scene-convergence`: what accuracy costs at scene scale (issue 23, part 4). A short
// variant of the shari scene (experiments/scenes/shari.toml: soft grains dropped into a mould
// and pressed by its lid; `count` grains, `frames` frames) runs by XPBD over substeps ×
// iterations and by vertex block descent over substeps × sweeps, and once more by XPBD at the
// finest setting, the converged reference. For each run it measures, at the end:
//  - the RMS distance of the grain centres from the reference's, over a grain length (grains
//    are matched by index: the fill drops them in the same order);
//  - the top centre and its error, the packing fraction half way up, the deepest overlap and
//    the kinetic energy;
//  - the wall time of the simulation.
// Writes scene_convergence.csv (a row per run, the reference last, with whether the run is on
// the Pareto front of the top's error against time), scene_convergence.png (that error against
// wall time, log–log, the front drawn through) and run_info.txt; each run's own folder holds
// its scene run. The front is drawn on the top, not on the centres: grains drop into the mould
// where room frees, so which grain lands where depends on every earlier step, and the centres'
// RMS sits at about two grain lengths for every run (measured); the top's height is the shape.
#pragma once

#include <filesystem>
#include <vector>

namespace rice::experiments {

struct SceneConvergenceSettings {
  std::filesystem::path scene = "experiments/scenes/shari.toml";
  int count = 100;
  int frames = 135;  ///< 4.5 s: dropped in, settled, pressed by the lid and left as it lifts
  std::vector<int> xpbd_substeps{240, 480, 960}, xpbd_iterations{1, 2};
  std::vector<int> vbd_substeps{5, 10, 20}, vbd_sweeps{5, 10};
  int reference_substeps = 1920, reference_iterations = 2;

  /// A few grains and frames and a 2 × 2 grid, for CI (seconds).
  static SceneConvergenceSettings quick();
};

/// Throws std::invalid_argument naming the setting out of range.
void validate(const SceneConvergenceSettings& settings);

void scene_convergence_study_command(const SceneConvergenceSettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
