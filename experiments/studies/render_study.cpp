// The rendering study; see render_study.hpp.
#include "experiments/studies/render_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/grain_heap.hpp"
#include "experiments/render/grain_plate.hpp"
#include "experiments/studies/render_models.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "shading/renderer.hpp"
#include "experiments/io/render_images.hpp"
#include "shading/subsurface_bake.hpp"

namespace rice::experiments {
namespace {

constexpr double kAbsorption = 20.0;  // W [%] of the grains

/// Renders of the plate at one image size and seed, each with its materials, sampler and
/// samples; counts them on the study's progress line.
struct PlateRuns {
  GrainPlate& plate;  // the bake writes its grains' light into it
  const shading::CdrfTable& cdrf;
  const RenderStudySettings& settings;
  Progress& progress;
  int done = 0;

  shading::Image operator()(const std::vector<shading::Material>& m, shading::SamplerKind sampler, int spp,
                            double& seconds) {
    shading::RenderStats stats;
    const shading::RenderSettings render{.width = settings.width, .height = settings.height, .samples_per_pixel = spp,
                                         .sampler = sampler, .seed = settings.seed};
    shading::Image image = shading::render(plate.scene, m, plate.lights, plate.camera, cdrf, render, &stats, {},
                                           stop_requested);
    stop_point();
    seconds = stats.seconds;
    return image;
  }
  void tick() { progress.update(++done); }
};

/// Each sampler at each sample count against the reference image: a row each; the RMSEs per
/// sampler, in the order of `samplers`.
std::vector<std::vector<double>> sweep_samplers(
    PlateRuns& run, const std::vector<shading::Material>& materials, const shading::Image& reference, double mean,
    const std::vector<std::pair<const char*, shading::SamplerKind>>& samplers, CsvTable& table) {
  std::vector<std::vector<double>> errors(samplers.size());
  double seconds = 0.0;
  for (size_t k = 0; k < samplers.size(); ++k) {
    for (const int spp : run.settings.samples) {
      const shading::Image image = run(materials, samplers[k].second, spp, seconds);
      const double rmse = shading::rms_difference(image, reference);
      errors[k].push_back(rmse);
      table.add_row({samplers[k].first, cell(spp), cell(seconds), cell(rmse), cell(rmse / mean)});
      run.tick();
    }
  }
  return errors;
}

/// The random-walk reference at growing photon counts, each against the last (a row each);
/// returns the last.
shading::Image sweep_photons(PlateRuns& run, const std::vector<shading::Material>& materials, double mean,
                             CsvTable& table) {
  const RenderStudySettings& settings = run.settings;
  const std::vector<shading::Medium> media(run.plate.grain_instances.size(), grain_medium(kAbsorption));
  std::vector<shading::Material> reference_materials = materials;
  reference_materials[0].kind = shading::MaterialKind::kSubsurfaceReference;
  std::vector<shading::Image> baked_images;
  std::vector<double> baked_seconds;
  double seconds = 0.0;
  for (const long long photons : settings.photons) {
    shading::BakeStats bake;
    shading::bake_subsurface(run.plate.scene, run.plate.grain_instances, media, run.plate.lights,
                             {.photons_per_light = photons, .seed = settings.seed}, &bake);
    run.tick();
    stop_point();
    baked_images.push_back(run(reference_materials, shading::SamplerKind::kSobol, settings.bake_render_spp, seconds));
    baked_seconds.push_back(bake.seconds + seconds);
    run.tick();
  }
  for (size_t k = 0; k + 1 < baked_images.size(); ++k) {
    const double rmse = shading::rms_difference(baked_images[k], baked_images.back());
    table.add_row({"random-walk", cell(static_cast<long>(settings.photons[k])), cell(baked_seconds[k]), cell(rmse),
                   cell(rmse / mean)});
  }
  return baked_images.back();
}

/// Equal error: the Sobol count whose error matches the largest independent count's, by
/// log–log interpolation along the Sobol curve.
double equal_error_spp(const std::vector<int>& samples, const std::vector<double>& independent,
                       const std::vector<double>& sobol) {
  const double target = independent.back();
  for (size_t i = 0; i + 1 < samples.size(); ++i) {
    const double e0 = sobol[i], e1 = sobol[i + 1];
    if (e0 >= target && e1 <= target) {
      const double t = std::log(e0 / target) / std::log(e0 / e1);
      return samples[i] * std::pow(static_cast<double>(samples[i + 1]) / samples[i], t);
    }
  }
  return samples.back();
}

void plot_render_study(const std::filesystem::path& folder, int largest_spp, double equal_spp, double cdrf_relative) {
  render_plot(folder, "render_study", R"(set terminal pngcairo size 900,600
set output 'render_study.png'
set datafile separator ','
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'wall time [s] (log)'
set ylabel 'RMSE against the reference image (log)'
set title 'Sobol reaches the error of )" + std::to_string(largest_spp) + R"( independent samples at )" +
                                     fixed(equal_spp, 0) + R"(; the CDRF sits )" + fixed(100 * cdrf_relative, 0) +
                                     R"(% RMS from the random walk'
set key left bottom
plot for [m in 'independent stratified sobol'] 'render_study.csv' using ((strcol(1) eq m) ? $3 : 1/0):4 \
       with linespoints pt 7 title m.' (CDRF, spp)', \
     '' using ((strcol(1) eq 'random-walk') ? $3 : 1/0):4 with linespoints pt 5 lw 2 title 'random walk (photons)', \
     '' using ((strcol(1) eq 'cdrf-vs-random-walk') ? $3 : 1/0):4 with points pt 9 ps 2 title 'CDRF against the random walk'
)");
}

}  // namespace

void validate(const RenderStudySettings& s) {
  if (s.width < 8 || s.height < 8 || s.width > 4096 || s.height > 4096)
    throw std::invalid_argument("study render: --width and --height must be in [8, 4096]");
  if (s.grains < 1 || s.grains > 10000) throw std::invalid_argument("study render: --grains must be in [1, 10000]");
  if (s.samples.empty()) throw std::invalid_argument("study render: give at least one --samples count");
  for (const int n : s.samples)
    if (n < 1 || n > 1 << 16) throw std::invalid_argument("study render: --samples counts must be in [1, 65536]");
  if (s.reference_spp < 1 || s.reference_spp > 1 << 20)
    throw std::invalid_argument("study render: --reference-spp must be in [1, 1048576]");
  if (s.photons.size() < 2) throw std::invalid_argument("study render: give at least two --photons counts");
  for (const long long n : s.photons)
    if (n < 1000 || n > 1'000'000'000LL) throw std::invalid_argument("study render: --photons must be in [1000, 1e9]");
  if (s.bake_render_spp < 1 || s.bake_render_spp > 1 << 16)
    throw std::invalid_argument("study render: --bake-spp must be in [1, 65536]");
  if (s.heap_grains < 1 || s.heap_grains > 100000) throw std::invalid_argument("study render: --heap-grains must be in [1, 100000]");
  if (s.models.samples.empty()) throw std::invalid_argument("study render: give at least one --model-samples count");
  for (const int n : s.models.samples)
    if (n < 1 || n > 1 << 16) throw std::invalid_argument("study render: --model-samples counts must be in [1, 65536]");
  if (s.models.reference_spp < 2) throw std::invalid_argument("study render: --path-reference-spp must be at least 2");
  for (const int k : s.models.bounces)
    if (k < 1 || k > 64) throw std::invalid_argument("study render: --bounces must be in [1, 64]");
  if (!s.samplers && !s.compare_models) throw std::invalid_argument("study render: --only-models and --no-models exclude each other");
}

namespace {

using RunInfo = std::vector<std::pair<std::string, std::string>>;

/// The samplers against a high-count CDRF image, and the CDRF against the random-walk bake.
void study_samplers_and_bake(const RenderStudySettings& settings, const shading::CdrfTable& cdrf,
                             const std::filesystem::path& folder, RunInfo& info) {
  GrainPlate plate;
  build_grain_plate(plate, settings.grains, settings.seed);
  const std::vector<shading::Material> materials = {
      rice_material(kAbsorption), {.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color::Constant(0.5f)}};
  const int runs = 1 + 3 * static_cast<int>(settings.samples.size()) + 2 * static_cast<int>(settings.photons.size()) + 1;
  Progress progress("study render: runs", runs);
  PlateRuns run{plate, cdrf, settings, progress};

  double seconds = 0.0;
  const shading::Image reference = run(materials, shading::SamplerKind::kSobol, settings.reference_spp, seconds);
  run.tick();
  write_png(folder / "reference_cdrf.png", tone_map(reference, 0.0));
  write_exr(folder / "reference_cdrf.exr", reference);
  CsvTable table({"method", "knob", "seconds", "rmse", "relative_rmse"});
  const double mean = shading::mean_radiance(reference);
  const std::vector<std::vector<double>> errors =
      sweep_samplers(run, materials, reference, mean,
                     {{"independent", shading::SamplerKind::kIndependent},
                      {"stratified", shading::SamplerKind::kStratified},
                      {"sobol", shading::SamplerKind::kSobol}},
                     table);
  const shading::Image best = sweep_photons(run, materials, mean, table);
  write_png(folder / "reference_random_walk.png", tone_map(best, 0.0));
  write_exr(folder / "reference_random_walk.exr", best);
  const shading::Image cdrf_image = run(materials, shading::SamplerKind::kSobol, settings.bake_render_spp, seconds);
  run.tick();
  progress.finish();
  const double cdrf_error = shading::rms_difference(cdrf_image, best);
  table.add_row({"cdrf-vs-random-walk", cell(settings.bake_render_spp), cell(seconds), cell(cdrf_error),
                 cell(cdrf_error / mean)});
  write_file_atomically(folder / "render_study.csv", table.text());

  const double equal_spp = equal_error_spp(settings.samples, errors[0], errors[2]);
  plot_render_study(folder, settings.samples.back(), equal_spp, cdrf_error / mean);
  info.insert(info.end(), {{"reference_spp", cell(settings.reference_spp)},
                           {"equal_error_sobol_spp", cell(equal_spp)},
                           {"cdrf_vs_random_walk_relative_rmse", cell(cdrf_error / mean)}});
  std::printf("study render: Sobol matches %d independent samples at %.0f; CDRF vs random walk %.1f%% RMS\n",
              settings.samples.back(), equal_spp, 100 * cdrf_error / mean);
}

/// Every model against the path-traced reference on the plate and the heap.
void study_models(const RenderStudySettings& settings, const shading::CdrfTable& cdrf,
                  const std::filesystem::path& folder, RunInfo& info) {
  RenderModelSettings models = settings.models;
  models.width = settings.width;
  models.height = settings.height;
  models.seed = settings.seed;
  models.absorption_percent = kAbsorption;
  Progress progress("study render: models", 2 * render_model_runs(models));
  int done = 0;
  const auto tick = [&] { progress.update(++done); };
  CsvTable table({"scene", "model", "spp", "seconds", "rmse", "relative_rmse"});
  std::vector<std::pair<std::string, RenderModelScene>> found;
  {
    GrainPlate plate;
    build_grain_plate(plate, settings.grains, settings.seed);
    found.emplace_back("plate", compare_render_models(plate, "plate", models, cdrf, folder, table, tick));
  }
  {
    GrainPlate heap;
    build_grain_heap(heap, settings.heap_grains, settings.seed);
    found.emplace_back("heap", compare_render_models(heap, "heap", models, cdrf, folder, table, tick));
  }
  progress.finish();
  write_file_atomically(folder / "render_models.csv", table.text());
  for (const auto& [name, f] : found) {
    plot_render_models(folder, name, f, models.bounces);
    info.insert(info.end(), {{name + "_reference_s", cell(f.reference_seconds)},
                             {name + "_reference_noise", cell(f.reference_noise)},
                             {name + "_best_model", f.best_model},
                             {name + "_best_relative_rms", cell(f.best_relative_rms)},
                             {name + "_best_s", cell(f.best_seconds)}});
    std::printf("study render: %s: best %s, %.1f%% RMS in %.1f s (the reference %.0f s, noise %.1f%%)\n", name.c_str(),
                f.best_model.c_str(), 100 * f.best_relative_rms, f.best_seconds, f.reference_seconds,
                100 * f.reference_noise);
  }
}

}  // namespace

void render_study_command(const RenderStudySettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  make_output_folder(folder);
  const shading::CdrfTable cdrf(513, 513);
  RunInfo info = {{"study", "render"},
                  {"width", cell(settings.width)},
                  {"height", cell(settings.height)},
                  {"grains", cell(settings.grains)},
                  {"heap_grains", cell(settings.heap_grains)},
                  {"seed", cell(static_cast<long>(settings.seed))}};
  if (settings.samplers) study_samplers_and_bake(settings, cdrf, folder, info);
  if (settings.compare_models) study_models(settings, cdrf, folder, info);
  info.emplace_back("wall_s", cell(seconds_since(start)));
  write_file_atomically(folder / "run_info.txt", run_info(info));
}

}  // namespace rice::experiments
