// The soft-instance study; see soft_instance_study.hpp.
#include "experiments/studies/soft_instance_study.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/render_images.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/render_command.hpp"
#include "experiments/render/rigid_fit.hpp"
#include "experiments/render/run_frames.hpp"

namespace rice::experiments {
namespace {

/// Each grain's rigid-fit residual, one row each; returns the residuals.
std::vector<double> fit_residuals(const SoftInstanceStudySettings& s, const std::filesystem::path& folder) {
  const std::filesystem::path frame = s.image.frame > 0 ? run_frame_path(s.image.run, s.image.frame) : run_frames(s.image.run).back();
  const RunVariants variants = read_run_variants(s.image.run);
  const std::vector<SoftGrain> grains =
      soft_run_grains(read_numeric_csv(s.image.run / "grains.csv"), read_numeric_csv(frame), variants);
  if (grains.empty()) throw std::runtime_error("soft-instances: " + frame.string() + " has no grain in the scene");
  CsvTable table({"grain", "variant", "residual_m"});
  std::vector<double> residuals;
  for (const SoftGrain& grain : grains) {
    residuals.push_back(fit_rigid_motion(variants.simulation[grain.variant].V, grain.swell, grain.x).residual);
    table.add_row({cell(grain.grain), cell(grain.variant), cell(residuals.back())});
  }
  write_file_atomically(folder / "soft_instance_grains.csv", table.text());
  return residuals;
}

void plot(const std::filesystem::path& folder) {
  render_plot(folder, "soft_instances", csv_plot_header("soft_instances", 800, 500) + R"(
set xlabel 'render wall time [s]'
set ylabel 'image RMS difference / mean radiance'
set logscale y
set key off
plot 'soft_instances.csv' using 4:($5 > 0 ? $5 : 1/0):(sprintf('%g m', $1)) with labels offset 0,1 notitle, \
     '' using 4:($5 > 0 ? $5 : 1/0) with linespoints pt 7
)");
}

}  // namespace

void validate(const SoftInstanceStudySettings& s) {
  validate(s.image);
  for (const double t : s.tolerances)
    if (!(t >= 0.0)) throw std::invalid_argument("--tolerances must be >= 0 [m]");
}

void soft_instance_study_command(const SoftInstanceStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  const std::vector<double> residuals = fit_residuals(s, folder);
  std::vector<double> tolerances = s.tolerances;
  tolerances.push_back(0.0);
  std::sort(tolerances.begin(), tolerances.end());
  tolerances.erase(std::unique(tolerances.begin(), tolerances.end()), tolerances.end());
  CsvTable table({"tolerance_m", "grains", "own_meshes", "render_s", "image_relative_rms"});
  const auto render_at = [&](double tolerance, const std::filesystem::path& images) {
    return timed_run_render(s.image, {.instance_tolerance = tolerance}, images);
  };
  render_at(0.0, folder / "warm_up");  // the first render also reads the run from disk
  std::filesystem::remove_all(folder / "warm_up");
  shading::Image reference;
  for (size_t k = 0; k < tolerances.size(); ++k) {
    const std::filesystem::path images = folder / ("tolerance_" + std::to_string(k));
    const double seconds = render_at(tolerances[k], images);
    const shading::Image image = read_exr(images / "render.exr");
    if (k == 0) reference = image;
    const double error = shading::rms_difference(image, reference) / shading::mean_radiance(reference);
    const long own = std::count_if(residuals.begin(), residuals.end(), [&](double r) { return r > tolerances[k]; });
    table.add_row({cell(tolerances[k]), cell(static_cast<long>(residuals.size())), cell(own), cell(seconds),
                   cell(error)});
    std::printf("soft-instances: tolerance %g m: %ld of %zu grains their own mesh, %.1f s, image RMS %.3g of the mean\n",
                tolerances[k], own, residuals.size(), seconds, error);
  }
  write_file_atomically(folder / "soft_instances.csv", table.text());
  plot(folder);
  write_file_atomically(folder / "run_info.txt", run_info({{"command", "study soft-instances"},
                                                           {"run", s.image.run.string()},
                                                           {"frame", s.image.frame > 0 ? cell(s.image.frame) : "last"},
                                                           {"width", cell(s.image.width)},
                                                           {"height", cell(s.image.height)},
                                                           {"samples_per_pixel", cell(s.image.samples_per_pixel)}}));
}

}  // namespace rice::experiments
