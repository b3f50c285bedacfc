// The path tracer's depth study; see path_depth_study.hpp.
#include "experiments/studies/path_depth_study.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/render_images.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/grain_plate.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "shading/path_tracer.hpp"
#include "shading/renderer.hpp"

namespace rice::experiments {
namespace {

constexpr double kPlateAbsorption = 20.0;  // W [%] of the grains, as in the render study

/// The plate and what its path-traced images share.
struct DepthRuns {
  const GrainPlate& plate;
  const PathDepthSettings& settings;
  std::vector<shading::Material> materials;
  std::vector<std::optional<shading::Medium>> media;
  Progress& progress;
  int done = 0;

  shading::Image path_traced(int depth, std::uint64_t seed, shading::PathTraceStats& stats) {
    shading::Image image = shading::path_trace(
        plate.scene, materials, media, plate.lights, plate.camera,
        {.width = settings.width, .height = settings.height, .samples_per_pixel = settings.samples_per_pixel,
         .seed = seed, .max_depth = depth},
        &stats, {}, stop_requested);
    stop_point();
    progress.update(++done);
    return image;
  }
};

void plot(const std::filesystem::path& folder, int chosen_depth, int reference_depth) {
  const std::string title = chosen_depth < reference_depth
                                ? std::to_string(chosen_depth) + " surface events are within 1% RMS of " +
                                      std::to_string(reference_depth)
                                : "no depth swept is within 1% RMS of " + std::to_string(reference_depth);
  render_plot(folder, "path_depth", csv_plot_header("path_depth", 900, 600) + kLogLogAxes + R"(set xlabel 'wall time [s]'
set ylabel 'RMS against the reference path tracer / mean radiance'
set title 'Path depth: )" + title + R"(' noenhanced
set key left bottom
plot 'path_depth.csv' using ((strcol(1) eq 'path-depth') ? $3 : 1/0):5 with linespoints pt 7 title 'path tracer, depth', \
     '' using ((strcol(1) eq 'path-depth') ? $3 : 1/0):5:2 with labels offset 0,1 font ',8' notitle, \
     '' using ((strcol(1) eq 'reference-noise') ? $3 : 1/0):5 with points pt 5 ps 2 title 'the reference noise', \
     '' using ((strcol(1) eq 'cdrf') ? $3 : 1/0):5 with points pt 9 ps 2 title 'the paper CDRF (direct light)'
)");
}

}  // namespace

PathDepthSettings PathDepthSettings::quick() {
  PathDepthSettings s;
  s.width = 32;
  s.height = 24;
  s.grains = 6;
  s.samples_per_pixel = 16;
  s.depths = {1, 2, 4};
  s.reference_depth = 16;
  s.cdrf_spp = 16;
  return s;
}

void validate(const PathDepthSettings& s) {
  if (s.width < 8 || s.height < 8 || s.width > 4096 || s.height > 4096)
    throw std::invalid_argument("study path-depth: --width and --height must be in [8, 4096]");
  if (s.grains < 1 || s.grains > 10000) throw std::invalid_argument("study path-depth: --grains must be in [1, 10000]");
  if (s.samples_per_pixel < 1 || s.cdrf_spp < 1)
    throw std::invalid_argument("study path-depth: --spp and --cdrf-spp must be at least 1");
  if (s.depths.empty()) throw std::invalid_argument("study path-depth: give at least one --depths value");
  for (const int d : s.depths)
    if (d < 1 || d >= s.reference_depth)
      throw std::invalid_argument("study path-depth: --depths must be in [1, --reference-depth)");
  if (s.reference_depth > 100000) throw std::invalid_argument("study path-depth: --reference-depth at most 100000");
  if (!(s.sun_radius > 0.0 && s.sun_radius < 1.0))
    throw std::invalid_argument("study path-depth: --sun-radius must be in (0, 1) rad");
}

void path_depth_study_command(const PathDepthSettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  GrainPlate plate;
  build_grain_plate(plate, settings.grains, settings.seed, static_cast<float>(settings.sun_radius));
  make_output_folder(folder);
  Progress progress("study path-depth: renders", static_cast<int>(settings.depths.size()) + 3);
  DepthRuns runs{plate, settings,
                 {rice_material(kPlateAbsorption), {.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color::Constant(0.5f)}},
                 {grain_medium(kPlateAbsorption)}, progress};

  shading::PathTraceStats stats;
  const shading::Image reference = runs.path_traced(settings.reference_depth, settings.seed, stats);
  const double reference_seconds = stats.seconds, mean = shading::mean_radiance(reference);
  write_png(folder / "reference.png", tone_map(reference, 0.0));
  write_exr(folder / "reference.exr", reference);
  CsvTable table({"method", "knob", "seconds", "rmse", "relative_rmse"});
  const auto add = [&](const char* method, double knob, double seconds, double rmse) {
    table.add_row({method, cell(knob), cell(seconds), cell(rmse), cell(rmse / mean)});
  };
  // The reference's noise: two independent images differ by √2 times it.
  const shading::Image second = runs.path_traced(settings.reference_depth, settings.seed + 1, stats);
  const double noise = shading::rms_difference(reference, second) / std::sqrt(2.0);
  add("reference-noise", settings.reference_depth, reference_seconds, noise);
  int chosen = settings.reference_depth;
  for (auto d = settings.depths.rbegin(); d != settings.depths.rend(); ++d) {
    const double rmse = shading::rms_difference(runs.path_traced(*d, settings.seed, stats), reference);
    add("path-depth", *d, stats.seconds, rmse);
    if (rmse < 0.01 * mean) chosen = *d;  // the truncation is within 1% of the mean radiance
  }
  const shading::CdrfTable cdrf(513, 513);
  shading::RenderStats cdrf_stats;
  const shading::Image direct =
      shading::render(plate.scene, runs.materials, plate.lights, plate.camera, cdrf,
                      {.width = settings.width, .height = settings.height, .samples_per_pixel = settings.cdrf_spp,
                       .seed = settings.seed},
                      &cdrf_stats, {}, stop_requested);
  stop_point();
  progress.update(++runs.done);
  progress.finish();
  const double cdrf_error = shading::rms_difference(direct, reference);
  add("cdrf", settings.cdrf_spp, cdrf_stats.seconds, cdrf_error);
  write_png(folder / "cdrf.png", tone_map(direct, 0.0));
  write_file_atomically(folder / "path_depth.csv", table.text());
  plot(folder, chosen, settings.reference_depth);
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"study", "path-depth"},
                                  {"width", cell(settings.width)},
                                  {"height", cell(settings.height)},
                                  {"grains", cell(settings.grains)},
                                  {"samples_per_pixel", cell(settings.samples_per_pixel)},
                                  {"reference_depth", cell(settings.reference_depth)},
                                  {"reference_s", cell(reference_seconds)},
                                  {"reference_relative_noise", cell(noise / mean)},
                                  {"chosen_depth", cell(chosen)},
                                  {"cdrf_relative_rmse", cell(cdrf_error / mean)},
                                  {"sun_radius_rad", cell(settings.sun_radius)},
                                  {"seed", cell(static_cast<long>(settings.seed))},
                                  {"wall_s", cell(seconds_since(start))}}));
  if (chosen < settings.reference_depth)
    std::printf("study path-depth: depth %d is within 1%% RMS of depth %d", chosen, settings.reference_depth);
  else
    std::printf("study path-depth: no depth swept is within 1%% RMS of depth %d", settings.reference_depth);
  std::printf(" (whose noise is %.2f%% of the mean); the CDRF is %.1f%% RMS off the path tracer\n",
              100.0 * noise / mean, 100.0 * cdrf_error / mean);
}

}  // namespace rice::experiments
