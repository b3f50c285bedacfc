// `rice study render`: what image accuracy costs in time, for the renderer's knobs.
//
// Scene: a plate of japonica grains (`grains` of them, from 4 generated variants, lying flat
// with random turns on a 2D grid) under a sun and a sky, seen from 40° above.
//  - Samplers: each of independent, stratified and Sobol at 1, 4, 16, … samples per pixel,
//    RMSE against a Sobol render at `reference_spp` and the wall time of each.
//  - CDRF against the random-walk reference: the subsurface bake at increasing photon counts
//    (each rendered at `bake_render_spp`), RMSE against the largest; and the CDRF render's
//    RMSE against that same best reference, its systematic error.
// Writes render_study.csv (method, knob value, seconds, RMSE), render_study.png (log–log,
// error against time), the reference images (PNG + EXR) and run_info.txt. The title states
// the equal-error sample count: how many Sobol samples match the error of the largest
// independent count.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rice::experiments {

struct RenderStudySettings {
  int width = 160, height = 120;
  int grains = 48;
  std::vector<int> samples = {1, 4, 16, 64, 200, 800};
  int reference_spp = 4096;
  std::vector<long long> photons = {10'000, 30'000, 100'000, 300'000};
  int bake_render_spp = 64;
  std::uint64_t seed = 1;
};

void validate(const RenderStudySettings& settings);

void render_study_command(const RenderStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
