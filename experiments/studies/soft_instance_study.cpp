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

/// Each grain's rigid-fit residual, in metres and in pixels of `footprint`, one row each.
void write_fit_residuals(const SoftInstanceStudySettings& s, const PixelFootprint& footprint,
                         const std::filesystem::path& folder) {
  const std::filesystem::path frame = s.image.frame > 0 ? run_frame_path(s.image.run, s.image.frame) : run_frames(s.image.run).back();
  const RunVariants variants = read_run_variants(s.image.run);
  const std::vector<SoftGrain> grains =
      soft_run_grains(read_numeric_csv(s.image.run / "grains.csv"), read_numeric_csv(frame), variants);
  if (grains.empty()) throw std::runtime_error("soft-instances: " + frame.string() + " has no grain in the scene");
  CsvTable table({"grain", "variant", "residual_m", "residual_pixels"});
  for (const SoftGrain& grain : grains) {
    const double residual = fit_rigid_motion(variants.simulation[grain.variant].V, grain.swell, grain.x).residual;
    const double pixel = footprint.at(grain.x.colwise().mean().transpose());
    table.add_row({cell(grain.grain), cell(grain.variant), cell(residual), cell(residual / pixel)});
  }
  write_file_atomically(folder / "soft_instance_grains.csv", table.text());
}

void plot(const std::filesystem::path& folder) {
  render_plot(folder, "soft_instances", csv_plot_header("soft_instances", 800, 500) + R"(
set xlabel 'render wall time [s]'
set ylabel 'image RMS difference / mean radiance'
set logscale y
set key off
plot 'soft_instances.csv' using 4:($5 > 0 ? $5 : 1/0):(sprintf('%g px', $1)) with labels offset 0,1 notitle, \
     '' using 4:($5 > 0 ? $5 : 1/0) with linespoints pt 7
)");
}

}  // namespace

void validate(const SoftInstanceStudySettings& s) {
  validate(s.image);
  for (const double t : s.tolerances)
    if (!(t >= 0.0)) throw std::invalid_argument("--tolerances must be >= 0 [pixels]");
}

void soft_instance_study_command(const SoftInstanceStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  std::vector<double> tolerances = s.tolerances;
  tolerances.push_back(0.0);
  std::sort(tolerances.begin(), tolerances.end());
  tolerances.erase(std::unique(tolerances.begin(), tolerances.end()), tolerances.end());
  CsvTable table({"tolerance_pixels", "grains", "own_meshes", "render_s", "image_relative_rms"});
  const auto render_at = [&](double tolerance, const std::filesystem::path& images) {
    return render_run_frame(s.image, {.instance_pixels = tolerance}, images);
  };
  // A first render, every grain an instance, reads the run from disk; its camera measures the
  // residuals in pixels.
  const RenderOutcome warm_up = render_at(1e6, folder / "warm_up");
  std::filesystem::remove_all(folder / "warm_up");
  write_fit_residuals(s, pixel_footprint(warm_up.camera, s.image.height), folder);
  shading::Image reference;
  long grains = 0;  // the reference's: every grain its own mesh
  for (size_t k = 0; k < tolerances.size(); ++k) {
    const std::filesystem::path images = folder / ("tolerance_" + std::to_string(k));
    const RenderOutcome outcome = render_at(tolerances[k], images);
    const shading::Image image = read_exr(images / "render.exr");
    if (k == 0) {
      reference = image;
      grains = outcome.own_meshes;
    }
    const double error = shading::rms_difference(image, reference) / shading::mean_radiance(reference);
    table.add_row({cell(tolerances[k]), cell(grains), cell(outcome.own_meshes), cell(outcome.wall_seconds),
                   cell(error)});
    std::printf("soft-instances: tolerance %g pixels: %d of %ld grains their own mesh, %.1f s, image RMS %.3g of "
                "the mean\n", tolerances[k], outcome.own_meshes, grains, outcome.wall_seconds, error);
    std::fflush(stdout);  // a line per render, as it ends
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
