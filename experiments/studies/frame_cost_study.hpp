// `rice study frame-cost`: what a full-size frame of a run costs, and how many samples it
// needs. On a window at the centre of the frame, rendered at the frame's full resolution (so
// its pixels are the frame's pixels), it renders
//  - a reference: the model under study (the translucent model with one bounce) by Sobol
//    samples at reference_spp, with another seed than the rest;
//  - the paper's sampling: independent samples at paper_spp (800), and its error;
//  - Sobol samples at each of sobol_spp; the equal-error sample count is where Sobol's error
//    falls to the paper's sampling's (log-log interpolated between the counts around it, or
//    extrapolated past the last, which run_info.txt says);
//  - each model (the CDRF, the translucent model with 0, 1, 2 bounces) at cost_spp;
// and estimates the whole frame's render time as the window's seconds per sample per pixel ×
// the frame's pixels × the sample count, at paper_spp and at the equal-error count. The
// window is the frame's centre, where the grains are: the estimate leans long. Writes
// frame_cost.csv (role, integrator, bounces, sampler, spp, seconds, relative_rmse,
// frame_seconds), frame_cost.png (error against estimated frame time), each window's images
// under window_<role>_<spp>/, and run_info.txt with the equal-error count and the estimates.
#pragma once

#include <filesystem>
#include <vector>

#include "experiments/render/render_command.hpp"

namespace rice::experiments {

struct FrameCostStudySettings {
  std::filesystem::path run;  ///< a scene run's output folder
  int frame = 0;              ///< 0: its last
  int width = 3840, height = 2160;
  int window_width = 480, window_height = 270;  ///< rendered at the frame's centre
  int reference_spp = 2048, paper_spp = 800, cost_spp = 32;
  std::vector<int> sobol_spp{4, 8, 16, 32, 64, 128, 256, 512};
  RenderIntegrator integrator = RenderIntegrator::kTranslucent;  ///< the model under study
  int bounces = 1;
};

/// Throws std::invalid_argument for a missing run, a window larger than the frame, or sample
/// counts below 1.
void validate(const FrameCostStudySettings& settings);

void frame_cost_study_command(const FrameCostStudySettings& settings, const std::filesystem::path& folder);

/// The sample count at which a falling error curve (spp ascending) reaches `target`,
/// interpolated in log(spp) against log(error), or extrapolated along the last segment when
/// the sweep ends above it; the first count when it starts below, infinity when the curve
/// does not fall. Throws std::invalid_argument unless there is one error per count.
double equal_error_spp(const std::vector<int>& spp, const std::vector<double>& error, double target);

}  // namespace rice::experiments
