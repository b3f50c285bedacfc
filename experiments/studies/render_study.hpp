// `rice study render`: what image accuracy costs in time, for the renderer's knobs and its
// models.
//
// Scene: a plate of japonica grains (`grains` of them, from 4 generated variants, lying flat
// with random turns on a 2D grid) under a sun and a sky, seen from 40° above; and for the
// models, a crop of a heap of `heap_grains` (grain_heap.hpp).
//  - Samplers: each of independent, stratified and Sobol at 1, 4, 16, … samples per pixel,
//    RMSE against a Sobol render at `reference_spp` and the wall time of each.
//  - CDRF against the random-walk reference: the subsurface bake at increasing photon counts
//    (each rendered at `bake_render_spp`), RMSE against the largest; and the CDRF render's
//    RMSE against that same best reference, its systematic error.
// Writes render_study.csv (method, knob value, seconds, RMSE), render_study.png (log–log,
// error against time), the reference images (PNG + EXR) and run_info.txt. The title states
// the equal-error sample count: how many Sobol samples match the error of the largest
// independent count.
//  - Models (render_models.hpp): the paper's CDRF and the translucent model with 0, 1 and 2
//    bounces against the path tracer, on the plate and the heap: render_models.csv,
//    render_models_plate.png, render_models_heap.png and each model's image.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "experiments/studies/render_models.hpp"

namespace rice::experiments {

struct RenderStudySettings {
  int width = 160, height = 120;
  int grains = 48;
  std::vector<int> samples = {1, 4, 16, 64, 200, 800};
  int reference_spp = 4096;
  std::vector<long long> photons = {10'000, 30'000, 100'000, 300'000};
  int bake_render_spp = 64;
  std::uint64_t seed = 1;
  bool samplers = true;        ///< the samplers and the random-walk bake
  bool compare_models = true;  ///< the models against the path tracer
  int heap_grains = 200;
  RenderModelSettings models;  ///< its samples and reference_spp (size and seed are the study's)

  /// Toy sizes for the test suite, the models only: seconds.
  static RenderStudySettings quick() {
    RenderStudySettings s;
    s.samplers = false;
    s.width = 32;
    s.height = 24;
    s.grains = 6;
    s.heap_grains = 20;
    s.samples = {1, 4};
    s.reference_spp = 16;
    s.photons = {2000, 4000};
    s.bake_render_spp = 2;
    s.models.samples = {2};
    s.models.reference_spp = 4;
    s.models.bounces = {1, 2};
    return s;
  }
};

void validate(const RenderStudySettings& settings);

void render_study_command(const RenderStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
