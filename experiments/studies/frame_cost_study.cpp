// The frame-cost study; see frame_cost_study.hpp.
#include "experiments/studies/frame_cost_study.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/render_images.hpp"
#include "experiments/io/run_info.hpp"

namespace rice::experiments {
namespace {

/// One render of the window.
struct WindowRender {
  std::string role;  ///< reference, paper, sobol or model
  RenderIntegrator integrator = RenderIntegrator::kTranslucent;
  int bounces = 0;
  shading::SamplerKind sampler = shading::SamplerKind::kSobol;
  int spp = 1;
};

struct WindowResult {
  double seconds = 0.0;  ///< the rendering itself, without reading the run and building the scene
  shading::Image image;
};

shading::PixelWindow centre_window(const FrameCostStudySettings& s) {
  const int x0 = (s.width - s.window_width) / 2, y0 = (s.height - s.window_height) / 2;
  return {x0, y0, x0 + s.window_width, y0 + s.window_height};
}

WindowResult render_window(const FrameCostStudySettings& s, const std::shared_ptr<const RunVariants>& variants,
                           const WindowRender& r, const std::filesystem::path& folder) {
  RenderCommandSettings c;
  c.run = s.run;
  c.variants = variants;
  c.frame = s.frame;
  c.integrator = r.integrator;
  c.bounces = r.bounces;
  c.render.width = s.width;
  c.render.height = s.height;
  c.render.crop = centre_window(s);
  c.render.samples_per_pixel = r.spp;
  c.render.sampler = r.sampler;
  c.render.seed = r.role == "reference" ? 2 : 1;  // the reference's noise is not the others'
  const std::filesystem::path images = folder / ("window_" + r.role + "_" + std::to_string(r.spp));
  const RenderOutcome outcome = render_command(c, images);
  return {outcome.stats.seconds, read_exr(images / "render.exr")};
}

void plot_frame_cost(const std::filesystem::path& folder) {
  render_plot(folder, "frame_cost", csv_plot_header("frame_cost", 800, 500) + R"(
set xlabel 'estimated time of the whole frame [s]'
set ylabel 'RMS error / mean radiance'
set logscale xy
plot 'frame_cost.csv' using ($5 > 0 && strcol(1) eq 'sobol' ? $8 : 1/0):7 with linespoints pt 7 title 'Sobol', \
     '' using (strcol(1) eq 'paper' ? $8 : 1/0):7 with points pt 5 ps 1.5 title 'independent (the paper''s sampling)', \
     '' using (strcol(1) eq 'sobol' ? $8 : 1/0):7:(sprintf('%d', $5)) with labels offset 0,1 notitle
)");
}

}  // namespace

double equal_error_spp(const std::vector<int>& spp, const std::vector<double>& error, double target) {
  if (spp.empty() || spp.size() != error.size()) throw std::invalid_argument("equal_error_spp: one error per count");
  if (error.front() <= target) return spp.front();
  if (spp.size() == 1) return std::numeric_limits<double>::infinity();
  size_t k = 1;
  while (k + 1 < spp.size() && error[k] > target) ++k;
  // The segment that reaches the target, or the last one: log e is linear in log n along it,
  // t = (log n − log n0) / (log n1 − log n0) = (log e − log e0) / (log e1 − log e0).
  if (!(error[k] < error[k - 1])) return std::numeric_limits<double>::infinity();
  const double t = std::log(target / error[k - 1]) / std::log(error[k] / error[k - 1]);
  return std::exp(std::log(spp[k - 1]) + t * std::log(static_cast<double>(spp[k]) / spp[k - 1]));
}

void validate(const FrameCostStudySettings& s) {
  if (!std::filesystem::is_directory(s.run))
    throw std::invalid_argument("--run: '" + s.run.string() + "' is not a run's folder");
  if (s.width < 1 || s.height < 1 || s.window_width < 1 || s.window_height < 1 || s.window_width > s.width ||
      s.window_height > s.height)
    throw std::invalid_argument("--window must be positive and fit in --width x --height");
  bool counts = s.reference_spp >= 1 && s.paper_spp >= 1 && s.cost_spp >= 1 && !s.sobol_spp.empty();
  for (size_t k = 0; k < s.sobol_spp.size(); ++k)
    counts = counts && s.sobol_spp[k] >= 1 && (k == 0 || s.sobol_spp[k] > s.sobol_spp[k - 1]);
  if (!counts) throw std::invalid_argument("sample counts must be >= 1, and --sobol-spp ascending");
  if (s.bounces < 0 || s.integrator == RenderIntegrator::kPath)
    throw std::invalid_argument("the model under study is the CDRF or the translucent model, with bounces >= 0");
}

void frame_cost_study_command(const FrameCostStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  const double frame_pixels = static_cast<double>(s.width) * s.height;
  const double window_pixels = static_cast<double>(s.window_width) * s.window_height;
  CsvTable table({"role", "integrator", "bounces", "sampler", "spp", "seconds", "relative_rmse", "frame_seconds"});
  // Every render is of the same run: its variants' curvature is smoothed once, not per render.
  const auto variants = std::make_shared<const RunVariants>(read_run_variants(s.run));
  const WindowResult reference =
      render_window(s, variants, {"reference", s.integrator, s.bounces, shading::SamplerKind::kSobol, s.reference_spp}, folder);
  const double mean = shading::mean_radiance(reference.image);
  const auto measure = [&](const WindowRender& r) {
    const WindowResult result = render_window(s, variants, r, folder);
    const double error = shading::rms_difference(result.image, reference.image) / mean;
    const double frame_seconds = result.seconds * frame_pixels / window_pixels;
    table.add_row({r.role, integrator_name(r.integrator), cell(r.bounces), sampler_name(r.sampler), cell(r.spp),
                   cell(result.seconds), cell(error), cell(frame_seconds)});
    std::printf("frame-cost: %s %s +%d %s %d spp: %.2f s, RMS %.3g of the mean, the frame %.0f s\n", r.role.c_str(),
                integrator_name(r.integrator).c_str(), r.bounces, sampler_name(r.sampler).c_str(), r.spp,
                result.seconds, error, frame_seconds);
    std::fflush(stdout);  // a line per render, as it ends
    return std::pair{error, frame_seconds / r.spp};
  };
  const auto [paper_error, paper_seconds_per_spp] =
      measure({"paper", s.integrator, s.bounces, shading::SamplerKind::kIndependent, s.paper_spp});
  std::vector<double> sobol_error;
  double sobol_seconds_per_spp = 0.0;
  for (const int spp : s.sobol_spp) {
    const auto [error, seconds_per_spp] =
        measure({"sobol", s.integrator, s.bounces, shading::SamplerKind::kSobol, spp});
    sobol_error.push_back(error);
    sobol_seconds_per_spp = seconds_per_spp;  // the largest count's: the least overhead per sample
  }
  for (const auto& [integrator, bounces] : std::vector<std::pair<RenderIntegrator, int>>{
           {RenderIntegrator::kCdrf, 0}, {RenderIntegrator::kTranslucent, 0}, {RenderIntegrator::kTranslucent, 1},
           {RenderIntegrator::kTranslucent, 2}})
    measure({"model", integrator, bounces, shading::SamplerKind::kSobol, s.cost_spp});
  write_file_atomically(folder / "frame_cost.csv", table.text());
  plot_frame_cost(folder);
  const double equal = equal_error_spp(s.sobol_spp, sobol_error, paper_error);
  const std::string reached = equal <= s.sobol_spp.back() ? "measured" : "extrapolated past the sweep";
  std::printf("frame-cost: Sobol reaches the error of %d independent samples at %.0f spp (%s); the frame: %.0f s at "
              "%d independent spp, %.0f s at the equal-error count\n",
              s.paper_spp, equal, reached.c_str(), paper_seconds_per_spp * s.paper_spp, s.paper_spp,
              sobol_seconds_per_spp * equal);
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "study frame-cost"},
                                  {"run", s.run.string()},
                                  {"frame", s.frame > 0 ? cell(s.frame) : "last"},
                                  {"frame_size", cell(s.width) + " x " + cell(s.height)},
                                  {"window", cell(s.window_width) + " x " + cell(s.window_height) + " at the centre"},
                                  {"model", integrator_name(s.integrator) + " +" + cell(s.bounces) + " bounces"},
                                  {"reference_spp", cell(s.reference_spp)},
                                  {"reference_seconds", cell(reference.seconds)},
                                  {"paper_spp", cell(s.paper_spp)},
                                  {"paper_relative_rmse", cell(paper_error)},
                                  {"equal_error_sobol_spp", cell(equal)},
                                  {"equal_error_sobol_spp_is", reached},
                                  {"frame_seconds_at_paper_spp", cell(paper_seconds_per_spp * s.paper_spp)},
                                  {"frame_seconds_at_equal_error_spp", cell(sobol_seconds_per_spp * equal)}}));
}

}  // namespace rice::experiments
