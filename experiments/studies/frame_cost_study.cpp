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
  int spp = 1;                 ///< a pixel's, or with adaptive sampling its most
  double adaptive_error = 0.0;  ///< 0: off
  int folder = 0;               ///< the k of window_<role>_<k>/: spp, or the adaptive render's index
};

struct WindowResult {
  double seconds = 0.0;  ///< the rendering itself, without reading the run and building the scene
  double mean_spp = 0.0;
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
  c.render.adaptive = {.relative_error = r.adaptive_error, .min_samples = s.adaptive_min_spp};
  const std::filesystem::path images =
      folder / ("window_" + r.role + "_" + std::to_string(r.adaptive_error > 0.0 ? r.folder : r.spp));
  const RenderOutcome outcome = render_command(c, images);
  const double pixels = static_cast<double>(s.window_width) * s.window_height;
  return {outcome.stats.seconds, static_cast<double>(outcome.stats.camera_rays) / pixels,
          read_exr(images / "render.exr")};
}

void plot_frame_cost(const std::filesystem::path& folder) {
  render_plot(folder, "frame_cost", csv_plot_header("frame_cost", 800, 500) + R"(
set xlabel 'estimated time of the whole frame [s]'
set ylabel 'RMS error / mean radiance'
set logscale xy
plot 'frame_cost.csv' using (strcol(1) eq 'sobol' ? $9 : 1/0):8 with linespoints pt 7 title 'Sobol', \
     '' using (strcol(1) eq 'adaptive' ? $9 : 1/0):8 with linespoints pt 9 title 'Sobol, adaptive', \
     '' using (strcol(1) eq 'paper' ? $9 : 1/0):8 with points pt 5 ps 1.5 title 'independent (the paper''s sampling)', \
     '' using (strcol(1) eq 'sobol' ? $9 : 1/0):8:(sprintf('%.0f', $6)) with labels offset 0,1 notitle, \
     '' using (strcol(1) eq 'adaptive' ? $9 : 1/0):8:(sprintf('%.0f', $6)) with labels offset 0,-1 notitle
)");
}

/// One window render's error against the reference and the whole frame's estimated time.
struct Measured {
  double error = 0.0, frame_seconds = 0.0, mean_spp = 0.0;
};

/// Renders windows, measures each against the reference and keeps a row of frame_cost.csv.
struct WindowMeasure {
  const FrameCostStudySettings& s;
  const std::shared_ptr<const RunVariants>& variants;
  const WindowResult& reference;
  const std::filesystem::path& folder;
  CsvTable table{{"role", "integrator", "bounces", "sampler", "adaptive_error", "spp", "seconds", "relative_rmse",
                  "frame_seconds"}};

  Measured operator()(const WindowRender& r) {
    const WindowResult result = render_window(s, variants, r, folder);
    const double error =
        shading::rms_difference(result.image, reference.image) / shading::mean_radiance(reference.image);
    const double frame_seconds =
        result.seconds * s.width * s.height / (static_cast<double>(s.window_width) * s.window_height);
    table.add_row({r.role, integrator_name(r.integrator), cell(r.bounces), sampler_name(r.sampler),
                   cell(r.adaptive_error), cell(result.mean_spp), cell(result.seconds), cell(error),
                   cell(frame_seconds)});
    std::printf("frame-cost: %s %s +%d %s %.4g spp: %.2f s, RMS %.3g of the mean, the frame %.0f s\n",
                r.role.c_str(), integrator_name(r.integrator).c_str(), r.bounces, sampler_name(r.sampler).c_str(),
                result.mean_spp, result.seconds, error, frame_seconds);
    std::fflush(stdout);  // a line per render, as it ends
    return {error, frame_seconds, result.mean_spp};
  }
};

/// The equal-error estimates, printed and in run_info.txt.
void write_summary(const FrameCostStudySettings& s, const WindowResult& reference, const Measured& paper,
                   const std::vector<Measured>& sobol, const std::vector<Measured>& adaptive,
                   const std::filesystem::path& folder) {
  std::vector<double> sobol_spp, sobol_error, adaptive_seconds, adaptive_error;
  for (size_t k = 0; k < sobol.size(); ++k) {
    sobol_spp.push_back(s.sobol_spp[k]);
    sobol_error.push_back(sobol[k].error);
  }
  for (const Measured& m : adaptive) {
    adaptive_seconds.push_back(m.frame_seconds);
    adaptive_error.push_back(m.error);
  }
  const double equal = equal_error_cost(sobol_spp, sobol_error, paper.error);
  const std::string reached = equal <= s.sobol_spp.back() ? "measured" : "extrapolated past the sweep";
  // the largest count's seconds per sample: the least overhead per sample
  const double sobol_seconds = sobol.back().frame_seconds / s.sobol_spp.back() * equal;
  const double adaptive_equal = adaptive.empty() ? std::numeric_limits<double>::quiet_NaN()
                                                 : equal_error_cost(adaptive_seconds, adaptive_error, paper.error);
  std::printf("frame-cost: Sobol reaches the error of %d independent samples at %.0f spp (%s); the frame: %.0f s at "
              "%d independent spp, %.0f s at the equal-error count, %.0f s adaptive\n",
              s.paper_spp, equal, reached.c_str(), paper.frame_seconds, s.paper_spp, sobol_seconds, adaptive_equal);
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
                                  {"paper_relative_rmse", cell(paper.error)},
                                  {"equal_error_sobol_spp", cell(equal)},
                                  {"equal_error_sobol_spp_is", reached},
                                  {"adaptive_spp", cell(s.adaptive_min_spp) + " to " + cell(s.adaptive_max_spp)},
                                  {"frame_seconds_at_paper_spp", cell(paper.frame_seconds)},
                                  {"frame_seconds_at_equal_error_spp", cell(sobol_seconds)},
                                  {"frame_seconds_adaptive_at_equal_error", cell(adaptive_equal)}}));
}

}  // namespace

double equal_error_cost(const std::vector<double>& cost, const std::vector<double>& error, double target) {
  if (cost.empty() || cost.size() != error.size()) throw std::invalid_argument("equal_error_cost: one error per cost");
  if (error.front() <= target) return cost.front();
  if (cost.size() == 1) return std::numeric_limits<double>::infinity();
  size_t k = 1;
  while (k + 1 < cost.size() && error[k] > target) ++k;
  // The segment that reaches the target, or the last one: log e is linear in log c along it,
  // t = (log c − log c0) / (log c1 − log c0) = (log e − log e0) / (log e1 − log e0).
  if (!(error[k] < error[k - 1])) return std::numeric_limits<double>::infinity();
  const double t = std::log(target / error[k - 1]) / std::log(error[k] / error[k - 1]);
  return std::exp(std::log(cost[k - 1]) + t * std::log(cost[k] / cost[k - 1]));
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
  bool adaptive = s.adaptive_min_spp >= 2 && s.adaptive_max_spp > s.adaptive_min_spp;
  for (size_t k = 0; k < s.adaptive_errors.size(); ++k)
    adaptive = adaptive && s.adaptive_errors[k] > 0.0 && s.adaptive_errors[k] < 1.0 &&
               (k == 0 || s.adaptive_errors[k] < s.adaptive_errors[k - 1]);
  if (!adaptive)
    throw std::invalid_argument(
        "--adaptive-errors must be in (0, 1) and descending, and 2 <= --adaptive-spp MIN < MAX");
  if (s.bounces < 0 || s.integrator == RenderIntegrator::kPath)
    throw std::invalid_argument("the model under study is the CDRF or the translucent model, with bounces >= 0");
}

void frame_cost_study_command(const FrameCostStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  // Every render is of the same run: its variants' curvature is smoothed once, not per render.
  const auto variants = std::make_shared<const RunVariants>(read_run_variants(s.run));
  const WindowResult reference =
      render_window(s, variants,
                    {"reference", s.integrator, s.bounces, shading::SamplerKind::kSobol, s.reference_spp}, folder);
  WindowMeasure measure{s, variants, reference, folder};
  const Measured paper = measure({"paper", s.integrator, s.bounces, shading::SamplerKind::kIndependent, s.paper_spp});
  std::vector<Measured> sobol, adaptive;
  for (const int spp : s.sobol_spp)
    sobol.push_back(measure({"sobol", s.integrator, s.bounces, shading::SamplerKind::kSobol, spp}));
  for (size_t k = 0; k < s.adaptive_errors.size(); ++k)
    adaptive.push_back(measure({"adaptive", s.integrator, s.bounces, shading::SamplerKind::kSobol, s.adaptive_max_spp,
                                s.adaptive_errors[k], static_cast<int>(k)}));
  for (const auto& [integrator, bounces] : std::vector<std::pair<RenderIntegrator, int>>{
           {RenderIntegrator::kCdrf, 0}, {RenderIntegrator::kTranslucent, 0}, {RenderIntegrator::kTranslucent, 1},
           {RenderIntegrator::kTranslucent, 2}})
    measure({"model", integrator, bounces, shading::SamplerKind::kSobol, s.cost_spp});
  write_file_atomically(folder / "frame_cost.csv", measure.table.text());
  plot_frame_cost(folder);
  write_summary(s, reference, paper, sobol, adaptive, folder);
}

}  // namespace rice::experiments
