// `rice study frame-cost`: what a full-size frame of a run costs, and how many samples it
// needs. On a window at the centre of the frame, rendered at the frame's full resolution (so
// its pixels are the frame's pixels), it renders
//  - a reference: the model under study (the translucent model with one bounce) by Sobol
//    samples at reference_spp, with another seed than the rest;
//  - the paper's sampling: independent samples at paper_spp (800), and its error;
//  - Sobol samples at each of sobol_spp; the equal-error sample count is where Sobol's error
//    falls to the paper's sampling's (log-log interpolated between the counts around it, or
//    extrapolated past the last, which run_info.txt says);
//  - Sobol samples with adaptive sampling (shading/adaptive_sampling.hpp) at each of
//    adaptive_errors, up to adaptive_max_spp a pixel;
//  - each model (the CDRF, the translucent model with 0, 1, 2 bounces) at cost_spp;
// and estimates the whole frame's render time as the window's seconds × the frame's pixels /
// the window's, at paper_spp, at the equal-error count and, interpolated the same way in
// time, at the adaptive renders' equal error. The window defaults to the frame's centre,
// where the grains are: the estimate leans long, and adaptive sampling gains least there; a
// window as large as the frame (at a smaller size) measures the whole picture. Writes
// frame_cost.csv (role, integrator, bounces, sampler, adaptive_error, spp (the mean, for an
// adaptive render), seconds, relative_rmse, frame_seconds), frame_cost.png (error against
// estimated frame time), each window's images under window_<role>_<k>/, and run_info.txt
// with the equal-error count and the estimates.
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
  std::vector<double> adaptive_errors{0.2, 0.1, 0.05, 0.03, 0.02};  ///< descending
  int adaptive_min_spp = 16, adaptive_max_spp = 1024;
  RenderIntegrator integrator = RenderIntegrator::kTranslucent;  ///< the model under study
  int bounces = 1;
};

/// Throws std::invalid_argument for a missing run, a window larger than the frame, or sample
/// counts below 1.
void validate(const FrameCostStudySettings& settings);

void frame_cost_study_command(const FrameCostStudySettings& settings, const std::filesystem::path& folder);

/// The cost (a sample count, or seconds) at which a falling error curve (cost ascending)
/// reaches `target`, interpolated in log(cost) against log(error), or extrapolated along the
/// last segment when the sweep ends above it; the first cost when it starts below, infinity
/// when the curve does not fall. Throws std::invalid_argument unless there is one error per
/// cost.
double equal_error_cost(const std::vector<double>& cost, const std::vector<double>& error, double target);

}  // namespace rice::experiments
