// The soft-curvature study; see soft_curvature_study.hpp.
#include "experiments/studies/soft_curvature_study.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/render_images.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/render_command.hpp"
#include "experiments/render/run_frames.hpp"
#include "shading/curvature.hpp"

namespace rice::experiments {
namespace {

double rms(const Eigen::VectorXd& v) { return std::sqrt(v.squaredNorm() / static_cast<double>(v.size())); }

struct CurvatureTotals {
  double relative_rms_sum = 0.0, worst = 0.0, seconds = 0.0;
  int grains = 0;
};

/// Each grain's deformed curvature against its rest curvature, one row each.
CsvTable compare_curvature(const SoftCurvatureStudySettings& s, const RunVariants& variants, CurvatureTotals& totals) {
  const std::filesystem::path frame = s.image.frame > 0 ? run_frame_path(s.image.run, s.image.frame) : run_frames(s.image.run).back();
  const std::vector<SoftGrain> grains =
      soft_run_grains(read_numeric_csv(s.image.run / "grains.csv"), read_numeric_csv(frame), variants);
  CsvTable table({"grain", "variant", "vertices", "relative_rms", "deformed_curvature_s"});
  Progress progress("soft-curvature: grains", static_cast<int>(grains.size()));
  for (const SoftGrain& grain : grains) {
    const auto start = std::chrono::steady_clock::now();
    const grains::SurfaceMesh mesh = deformed_render_mesh(grain, variants);
    const Eigen::VectorXd deformed = shading::vertex_mean_curvature(mesh.V, mesh.F);
    const double seconds = seconds_since(start);
    const Eigen::VectorXd rest = variants.shading[grain.variant].curvature / grain.swell;
    const double relative = rms(deformed - rest) / rms(deformed);
    table.add_row({cell(grain.grain), cell(grain.variant), cell(static_cast<long>(mesh.V.rows())), cell(relative),
                   cell(seconds)});
    totals.relative_rms_sum += relative;
    totals.worst = std::max(totals.worst, relative);
    totals.seconds += seconds;
    progress.update(++totals.grains);
  }
  progress.finish();
  if (totals.grains == 0) throw std::runtime_error("soft-curvature: " + frame.string() + " has no grain in the scene");
  return table;
}

}  // namespace

void validate(const SoftCurvatureStudySettings& s) {
  validate(s.image);
}

void soft_curvature_study_command(const SoftCurvatureStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  const RunVariants variants = read_run_variants(s.image.run, 0.0);  // the meshes' own curvature
  CurvatureTotals totals;
  const CsvTable table = compare_curvature(s, variants, totals);
  write_file_atomically(folder / "soft_curvature.csv", table.text());
  // Every grain its own mesh, so that each is shaded as the option says.
  const auto render_with = [&](SoftCurvature curvature, const std::filesystem::path& images) {
    return render_run_frame(s.image, {.curvature = curvature, .instance_pixels = 0.0}, images).wall_seconds;
  };
  const double rest_s = render_with(SoftCurvature::kRest, folder / "rest");
  const double deformed_s = render_with(SoftCurvature::kDeformed, folder / "deformed");
  const shading::Image rest = read_exr(folder / "rest" / "render.exr");
  const shading::Image deformed = read_exr(folder / "deformed" / "render.exr");
  const double image_error = shading::rms_difference(rest, deformed) / shading::mean_radiance(deformed);
  const double mean_relative = totals.relative_rms_sum / totals.grains;
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "study soft-curvature"},
                                  {"run", s.image.run.string()},
                                  {"frame", s.image.frame > 0 ? cell(s.image.frame) : "last"},
                                  {"grains", cell(totals.grains)},
                                  {"curvature_relative_rms_mean", cell(mean_relative)},
                                  {"curvature_relative_rms_worst", cell(totals.worst)},
                                  {"deformed_curvature_s", cell(totals.seconds)},
                                  {"image_relative_rms", cell(image_error)},
                                  {"render_rest_s", cell(rest_s)},
                                  {"render_deformed_s", cell(deformed_s)}}));
  std::printf("soft-curvature: %d grains, curvature RMS %.3g (worst %.3g) of H, %.2f s to recompute; image RMS %.3g "
              "of the mean; renders %.1f s (rest) and %.1f s (deformed)\n",
              totals.grains, mean_relative, totals.worst, totals.seconds, image_error, rest_s, deformed_s);
}

}  // namespace rice::experiments
