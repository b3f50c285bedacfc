// `rice study soft-curvature`: what a soft grain's shading curvature costs (issue 23, part 3).
// A soft run's render meshes ride on their deformed simulation meshes; the CDRF's curvature
// can be each variant's rest curvature scaled by 1/P (free), or recomputed on every deformed
// grain. On one frame of a soft run (`rice run` with body = "soft"), this study measures:
//  - per grain, the RMS of H_deformed − H_rest/P over its vertices, relative to the RMS of
//    H_deformed, and the time the recomputation took;
//  - the frame rendered both ways: the image RMS difference relative to the mean radiance,
//    and each render's wall time.
// Writes soft_curvature.csv (a row per grain), the two renders (rest/, deformed/) and
// run_info.txt with the summary.
#pragma once

#include <filesystem>

#include "experiments/render/render_command.hpp"

namespace rice::experiments {

struct SoftCurvatureStudySettings {
  RunFrameImage image;
};

void validate(const SoftCurvatureStudySettings& settings);

void soft_curvature_study_command(const SoftCurvatureStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
