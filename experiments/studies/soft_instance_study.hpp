// `rice study soft-instances`: what drawing near-rigid soft grains as instances costs and saves
// (issue 23, part 3). A soft grain is drawn as its own deformed mesh, or, when its simulation
// vertices all lie within a tolerance of its best rigid fit (rigid_fit.hpp), as an instance of
// its variant, sharing the variant's hierarchy as a rigid grain does. The tolerance is a
// fraction of a pixel's footprint at the grain. On one frame of a soft run this study writes:
//  - soft_instance_grains.csv: each grain's fit residual, in metres and in pixels;
//  - soft_instances.csv: per tolerance, the grains drawn as their own mesh, the render's wall
//    time and the image's RMS difference from the render with every grain its own mesh
//    (tolerance 0), relative to its mean radiance; soft_instances.png plots error against time;
//  - the renders (tolerance_N/) and run_info.txt.
#pragma once

#include <filesystem>
#include <vector>

#include "experiments/render/render_command.hpp"

namespace rice::experiments {

struct SoftInstanceStudySettings {
  RunFrameImage image;
  /// [pixels] tolerances to sweep; 0 is the reference and always run
  std::vector<double> tolerances{0.0, 0.02, 0.05, 0.1, 0.25, 1.0, 4.0};
};

/// Throws std::invalid_argument for a bad image (validate(RunFrameImage)) or a tolerance below 0.
void validate(const SoftInstanceStudySettings& settings);

void soft_instance_study_command(const SoftInstanceStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
