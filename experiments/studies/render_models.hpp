// `rice study render`'s comparison of the rendering models against the path-traced
// reference (issue 24 §2), on the plate of grains and on a crop of a heap:
//  - cdrf: the paper's CDRF, direct light (renderer.hpp);
//  - translucent: the CDRF with the light through the grain, τ(d, cos θ), direct light;
//  - translucent+k: the same with k bounces of light between grains and the ground (the path
//    tracer's fast model, path_tracer.hpp, depth k + 1), for each k of `bounces`;
//  - the reference: the path tracer through every grain's medium, depth 64, rendered as two
//    halves of its samples on two seeds, whose difference gives its own noise.
// Each model at each sample count: wall time and RMS against the reference over the
// reference's mean radiance.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "experiments/io/csv_table.hpp"
#include "experiments/render/grain_plate.hpp"
#include "shading/cdrf.hpp"

namespace rice::experiments {

struct RenderModelSettings {
  int width = 160, height = 120;
  std::vector<int> samples = {4, 16, 64, 256};
  int reference_spp = 256;
  std::vector<int> bounces = {1, 2, 4, 8};
  double absorption_percent = 20.0;
  std::uint64_t seed = 1;
};

/// What one scene's comparison found, beside its rows.
struct RenderModelScene {
  double reference_seconds = 0.0, reference_noise = 0.0;  // noise relative to the mean radiance
  double best_relative_rms = 0.0;  // the fastest model within 5% RMS: its error (or the best one's)
  double best_seconds = 0.0;       // and its time
  std::string best_model;
};

/// Renders `scene` (grains material 0, ground 1) with every model at every sample count and
/// the reference; adds a row per render to `table` (scene, model, spp, seconds, rmse,
/// relative_rmse) and writes <name>_reference.{png,exr} and <name>_<model>.png (the largest
/// count) into `folder`. `tick` is called after each render.
RenderModelScene compare_render_models(const GrainPlate& scene, const std::string& name,
                                       const RenderModelSettings& settings, const shading::CdrfTable& cdrf,
                                       const std::filesystem::path& folder, CsvTable& table, const std::function<void()>& tick);

/// Renders a scene's comparison makes (for a progress total).
int render_model_runs(const RenderModelSettings& settings);

/// render_models_<name>.png: error against time per model, the reference's time and noise.
void plot_render_models(const std::filesystem::path& folder, const std::string& name, const RenderModelScene& found,
                        const std::vector<int>& bounces);

}  // namespace rice::experiments
