// Figure 13 driver; see figure13.hpp.
#include "experiments/figures/figure13.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/render_images.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "grains/absorption_table.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"
#include "grains/water_content.hpp"
#include "shading/cielab.hpp"
#include "shading/path_tracer.hpp"
#include "shading/renderer.hpp"
#include "shading/subsurface_bake.hpp"

namespace rice::experiments {

namespace {

/// One grain lying flat, repeated along x, a material each: only the water content differs
/// between them. Material n is the dark cloth under them.
struct GrainRow {
  shading::RenderScene scene;
  std::vector<shading::Material> materials;
  std::vector<double> absorption;  ///< W per grain [%]
  double pitch = 0.0;              ///< between grain centres along x [m]
  double height = 0.0;             ///< the grain's thickness [m]
  int n = 0;
};

void make_row(const Figure13Settings& settings, const grains::Grain& grain, GrainRow& row) {
  const grains::WaterContentModel model(grains::read_absorption_table(grains::default_absorption_table()));
  const int prototype = add_grain_prototype(row.scene, grain.render.V, grain.render.F);
  const Eigen::Vector3d lo = grain.render.V.colwise().minCoeff(), hi = grain.render.V.colwise().maxCoeff();
  row.pitch = 1.25 * (hi.x() - lo.x());
  row.height = hi.z() - lo.z();
  row.n = static_cast<int>(settings.soak_minutes.size());
  for (int i = 0; i < row.n; ++i) {
    row.absorption.push_back(model.absorption_percent(settings.soak_minutes[i], settings.temperature_c));
    row.materials.push_back(rice_material(row.absorption.back()));
    Eigen::Affine3d place = Eigen::Affine3d::Identity();
    place.translation() = Eigen::Vector3d(i * row.pitch - 0.5 * (lo.x() + hi.x()), -0.5 * (lo.y() + hi.y()), -lo.z());
    row.scene.add_instance(prototype, place, i);
  }
  row.materials.push_back({.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color::Constant(0.05f)});
  const double n = row.n, pitch = row.pitch;
  add_ground(row.scene, -n * pitch, -n * pitch, 2 * n * pitch, n * pitch, 0.0, row.n);  // a dark cloth
  row.scene.commit();
}

/// The sun high behind the row, a dim sky.
shading::Lights row_lights() {
  shading::Lights lights;
  lights.suns.push_back({.direction = Eigen::Vector3f(0.0f, 0.6f, 0.8f), .irradiance = shading::Color::Constant(4.0f)});
  lights.environment.constant = shading::Color::Constant(0.15f);
  return lights;
}

/// The row, n pitches wide, fills the image's width, seen from 25° above the front: each grain
/// shows its lit top, its terminator and its shaded front.
shading::Camera row_camera(const GrainRow& row, double aspect) {
  shading::Camera camera;
  camera.vertical_fov_degrees = 10.0;
  camera.target = Eigen::Vector3d(0.5 * (row.n - 1) * row.pitch, 0.0, 0.5 * row.height);
  const double half_width = std::tan(0.5 * camera.vertical_fov_degrees * std::numbers::pi / 180.0) * aspect;
  const double distance = 0.5 * row.n * row.pitch / half_width;
  const double elevation = 25.0 * std::numbers::pi / 180.0;
  camera.position = camera.target + distance * Eigen::Vector3d(0.0, -std::cos(elevation), std::sin(elevation));
  return camera;
}

/// What one image of the row needs besides its materials.
struct RowView {
  const shading::Lights& lights;
  const shading::Camera& camera;
  const shading::CdrfTable& cdrf;
  const shading::RenderSettings& render;
};

shading::Image render_row(const GrainRow& row, const std::vector<shading::Material>& materials, const RowView& view,
                          const std::string& label, shading::RenderStats& stats) {
  Progress progress("figure 13: " + label + " tiles", shading::tile_count(view.render));
  shading::Image image = shading::render(row.scene, materials, view.lights, view.camera, view.cdrf, view.render, &stats,
                                         [&](int done, int) { progress.update(done); }, stop_requested);
  progress.finish();
  stop_point();
  return image;
}

/// The reference: each grain's subsurface light baked by the random walk in its own medium,
/// then the row rendered with the baked light.
shading::Image render_reference(GrainRow& row, const RowView& view, const Figure13Settings& settings,
                                shading::BakeStats& bake_stats, shading::RenderStats& stats) {
  std::vector<int> grain_instances(row.n);
  std::vector<shading::Medium> media;
  std::vector<shading::Material> materials = row.materials;
  for (int i = 0; i < row.n; ++i) {
    grain_instances[i] = i;
    media.push_back(grain_medium(row.absorption[i]));
    materials[i].kind = shading::MaterialKind::kSubsurfaceReference;
  }
  {
    Progress progress("figure 13: random-walk bake", 1);
    shading::bake_subsurface(row.scene, grain_instances, media, view.lights,
                             {.photons_per_light = settings.photons, .seed = settings.seed}, &bake_stats);
    progress.finish();
  }
  stop_point();
  return render_row(row, materials, view, "reference", stats);
}

/// The row path-traced: each grain its own medium, the cloth Lambertian.
shading::Image render_path_traced(const GrainRow& row, const RowView& view, const Figure13Settings& settings,
                                  shading::PathTraceStats& stats) {
  std::vector<std::optional<shading::Medium>> media;
  for (int i = 0; i < row.n; ++i) media.push_back(grain_medium(row.absorption[i]));
  Progress progress("figure 13: path-traced tiles", shading::tile_count(view.render));
  shading::Image image = shading::path_trace(
      row.scene, row.materials, media, view.lights, view.camera,
      {.width = settings.width, .height = settings.height, .samples_per_pixel = settings.path_spp, .seed = settings.seed},
      &stats, [&](int done, int) { progress.update(done); }, stop_requested);
  progress.finish();
  stop_point();
  return image;
}

/// Per grain, from the pixels whose centre ray hits it: the mean radiance of its sun side and
/// its far side in both images, and their RMS difference; and how visibly the driest and the
/// wettest grain differ, ΔE*ab of their sides' mean displayed colours (after the tone curve).
struct GrainRadiance {
  std::vector<double> lit, shaded, reference_lit, reference_shaded, rms, mean;
  double worst_relative = 0.0;  ///< the largest rms / mean
  double delta_e_lit = 0.0, delta_e_shaded = 0.0, reference_delta_e_lit = 0.0, reference_delta_e_shaded = 0.0;
};

/// Mean displayed colour (aces_filmic of each channel, linear) of pixels summed into `sum`.
Eigen::Vector3d displayed(const Eigen::Vector3d& sum, int pixels) { return sum / std::max(1, pixels); }

Eigen::Vector3d tone_curve(const shading::Color& radiance) {
  return {aces_filmic(radiance[0]), aces_filmic(radiance[1]), aces_filmic(radiance[2])};
}

GrainRadiance measure_grains(const GrainRow& row, const shading::Image& image, const shading::Image& reference,
                             const RowView& view) {
  const int n = row.n, width = view.render.width, height = view.render.height;
  const double aspect = static_cast<double>(width) / height;
  GrainRadiance m;
  m.lit.assign(n, 0.0);
  m.shaded = m.reference_lit = m.reference_shaded = m.rms = m.mean = m.lit;
  std::vector<double> squared(n, 0.0);
  std::vector<int> lit_count(n, 0), shaded_count(n, 0);
  // Displayed colour sums per grain: [side][grain], side 0 lit, 1 shaded; image, reference.
  std::vector<std::vector<Eigen::Vector3d>> shown(2, std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero()));
  std::vector<std::vector<Eigen::Vector3d>> shown_reference = shown;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const shading::CameraRay r = view.camera.ray((x + 0.5) / width, (y + 0.5) / height, 0, 0, aspect);
      const auto hit = row.scene.intersect({r.origin, r.direction});
      if (!hit || hit->instance >= n) continue;
      const int g = hit->instance;
      const bool sunny = hit->shading_normal.dot(view.lights.suns[0].direction.normalized()) > 0.0f;
      (sunny ? m.lit : m.shaded)[g] += image.at(x, y).mean();
      (sunny ? m.reference_lit : m.reference_shaded)[g] += reference.at(x, y).mean();
      ++(sunny ? lit_count : shaded_count)[g];
      shown[sunny ? 0 : 1][g] += tone_curve(image.at(x, y));
      shown_reference[sunny ? 0 : 1][g] += tone_curve(reference.at(x, y));
      squared[g] += (image.at(x, y) - reference.at(x, y)).square().mean();
    }
  for (int i = 0; i < n; ++i) {
    const int pixels = std::max(1, lit_count[i] + shaded_count[i]);
    m.mean[i] = (m.lit[i] + m.shaded[i]) / pixels;
    m.lit[i] /= std::max(1, lit_count[i]);
    m.shaded[i] /= std::max(1, shaded_count[i]);
    m.reference_lit[i] /= std::max(1, lit_count[i]);
    m.reference_shaded[i] /= std::max(1, shaded_count[i]);
    m.rms[i] = std::sqrt(squared[i] / pixels);
    m.worst_relative = std::max(m.worst_relative, m.rms[i] / m.mean[i]);
  }
  const int last = n - 1;
  const auto delta_e = [&](const std::vector<std::vector<Eigen::Vector3d>>& sums, int side, const std::vector<int>& count) {
    return shading::delta_e76(displayed(sums[side][0], count[0]), displayed(sums[side][last], count[last]));
  };
  m.delta_e_lit = delta_e(shown, 0, lit_count);
  m.delta_e_shaded = delta_e(shown, 1, shaded_count);
  m.reference_delta_e_lit = delta_e(shown_reference, 0, lit_count);
  m.reference_delta_e_shaded = delta_e(shown_reference, 1, shaded_count);
  return m;
}

/// A row per grain; `m` compares the CDRF with the bake, `p` the CDRF with the path tracer.
CsvTable figure13_table(const Figure13Settings& settings, const GrainRow& row, const GrainRadiance& m,
                        const GrainRadiance& p) {
  CsvTable table({"soak_minutes", "absorption_percent", "sigma0_mm", "albedo", "lit_radiance", "shaded_radiance",
                  "shaded_over_lit", "reference_lit_radiance", "reference_shaded_radiance", "reference_shaded_over_lit",
                  "rms_difference", "relative_rms_difference", "path_lit_radiance", "path_shaded_radiance",
                  "path_shaded_over_lit", "rms_difference_from_path", "relative_rms_difference_from_path"});
  for (int i = 0; i < row.n; ++i)
    table.add_row({cell(settings.soak_minutes[i]), cell(row.absorption[i]), cell(1e3 * row.materials[i].sigma0),
                   cell(static_cast<double>(row.materials[i].albedo[0])), cell(m.lit[i]), cell(m.shaded[i]),
                   cell(m.shaded[i] / m.lit[i]), cell(m.reference_lit[i]), cell(m.reference_shaded[i]),
                   cell(m.reference_shaded[i] / m.reference_lit[i]), cell(m.rms[i]), cell(m.rms[i] / m.mean[i]),
                   cell(p.reference_lit[i]), cell(p.reference_shaded[i]), cell(p.reference_shaded[i] / p.reference_lit[i]),
                   cell(p.rms[i]), cell(p.rms[i] / p.mean[i])});
  return table;
}

/// figure13.png: the three rows, labelled with each grain's soak and W.
void plot_figure13(const std::filesystem::path& folder, const Figure13Settings& settings, const GrainRow& row,
                   const GrainRadiance& m, const GrainRadiance& p) {
  const int n = row.n;
  std::string labels;
  for (int i = 0; i < n; ++i) {
    labels += "set label " + std::to_string(i + 1) + " '" + fixed(settings.soak_minutes[i], 0) + " min, W = " +
              fixed(row.absorption[i], 1) + "%' at graph " + fixed((i + 0.5) / n, 3) + ", 0.08 center front tc rgb 'white'\n";
  }
  const std::string size = std::to_string(settings.width) + "," + std::to_string(3 * settings.height + 100);
  const std::string range = "set xrange [0:" + std::to_string(settings.width - 1) + "]\nset yrange [0:" +
                            std::to_string(settings.height - 1) + "]\n";
  render_plot(folder, "figure13", "set terminal pngcairo size " + size + R"(
set output 'figure13.png'
set multiplot layout 3,1 title 'Soaked longer at )" + fixed(settings.temperature_c, 0) +
                                      R"( °C, shaded/lit )" + fixed(m.shaded.front() / m.lit.front(), 2) +
                                      " → " + fixed(m.shaded.back() / m.lit.back(), 2) + " (CDRF), " +
                                      fixed(m.reference_shaded.front() / m.reference_lit.front(), 2) + " → " +
                                      fixed(m.reference_shaded.back() / m.reference_lit.back(), 2) + " (random walk), " +
                                      fixed(p.reference_shaded.front() / p.reference_lit.front(), 2) + " → " +
                                      fixed(p.reference_shaded.back() / p.reference_lit.back(), 2) + R"( (path traced)'
unset border
unset tics
unset key
set margins 0, 0, 0, 3
)" + range + labels + R"(set title 'CDRF'
plot 'figure13_render.png' binary filetype=png with rgbimage
set title 'random-walk bake (CDRF differs by up to )" + fixed(100 * m.worst_relative, 0) + R"(% RMS per grain)'
plot 'figure13_reference.png' binary filetype=png with rgbimage
set title 'path traced, the reference (its rare sun glints on the smooth surface dominate the RMS per grain)'
plot 'figure13_path.png' binary filetype=png with rgbimage
unset multiplot
)");
}

}  // namespace

void validate(const Figure13Settings& s) {
  if (s.soak_minutes.empty() || s.soak_minutes.size() > 12)
    throw std::invalid_argument("figure 13: give 1 to 12 --soak-minutes");
  for (const double t : s.soak_minutes)
    if (!(t > 0.0 && t <= 10000.0)) throw std::invalid_argument("figure 13: --soak-minutes must be in (0, 10000]");
  if (s.width < 16 || s.height < 16 || s.width > 16384 || s.height > 16384)
    throw std::invalid_argument("figure 13: --width and --height must be in [16, 16384]");
  if (s.samples_per_pixel < 1 || s.samples_per_pixel > 1 << 20)
    throw std::invalid_argument("figure 13: --spp must be in [1, 1048576]");
  if (s.photons < 1000 || s.photons > 1'000'000'000LL)
    throw std::invalid_argument("figure 13: --photons must be in [1000, 1e9]");
  if (s.path_spp < 1 || s.path_spp > 1 << 20) throw std::invalid_argument("figure 13: --path-spp must be in [1, 1048576]");
}

void figure13_command(const Figure13Settings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  const grains::Grain grain = grains::make_grain(recipe, settings.seed, 1.0);
  make_output_folder(folder);
  GrainRow row;
  make_row(settings, grain, row);
  const shading::Lights lights = row_lights();
  const shading::Camera camera = row_camera(row, static_cast<double>(settings.width) / settings.height);
  const shading::CdrfTable cdrf(513, 513);
  const shading::RenderSettings render{.width = settings.width, .height = settings.height,
                                       .samples_per_pixel = settings.samples_per_pixel, .seed = settings.seed};
  const RowView view{lights, camera, cdrf, render};
  shading::RenderStats cdrf_stats, reference_stats;
  shading::BakeStats bake_stats;
  const shading::Image image = render_row(row, row.materials, view, "CDRF", cdrf_stats);
  const shading::Image reference = render_reference(row, view, settings, bake_stats, reference_stats);
  shading::PathTraceStats path_stats;
  const shading::Image path = render_path_traced(row, view, settings, path_stats);
  const GrainRadiance m = measure_grains(row, image, reference, view);
  const GrainRadiance p = measure_grains(row, image, path, view);

  write_file_atomically(folder / "figure13.csv", figure13_table(settings, row, m, p).text());
  write_png(folder / "figure13_render.png", tone_map(image, 0.0));
  write_exr(folder / "figure13_render.exr", image);
  write_png(folder / "figure13_reference.png", tone_map(reference, 0.0));
  write_exr(folder / "figure13_reference.exr", reference);
  write_png(folder / "figure13_path.png", tone_map(path, 0.0));
  write_exr(folder / "figure13_path.exr", path);
  plot_figure13(folder, settings, row, m, p);
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"figure", "13"},
                                  {"temperature_c", cell(settings.temperature_c)},
                                  {"width", cell(settings.width)},
                                  {"height", cell(settings.height)},
                                  {"samples_per_pixel", cell(settings.samples_per_pixel)},
                                  {"photons_per_light_per_grain", cell(static_cast<long>(settings.photons))},
                                  {"seed", cell(static_cast<long>(settings.seed))},
                                  {"cdrf_render_s", cell(cdrf_stats.seconds)},
                                  {"reference_bake_s", cell(bake_stats.seconds)},
                                  {"reference_render_s", cell(reference_stats.seconds)},
                                  {"worst_relative_rms_difference", cell(m.worst_relative)},
                                  {"delta_e_driest_wettest_lit", cell(m.delta_e_lit)},
                                  {"delta_e_driest_wettest_shaded", cell(m.delta_e_shaded)},
                                  {"reference_delta_e_driest_wettest_lit", cell(m.reference_delta_e_lit)},
                                  {"reference_delta_e_driest_wettest_shaded", cell(m.reference_delta_e_shaded)},
                                  {"path_spp", cell(settings.path_spp)},
                                  {"path_render_s", cell(path_stats.seconds)},
                                  {"worst_relative_rms_difference_from_path", cell(p.worst_relative)},
                                  {"path_delta_e_driest_wettest_lit", cell(p.reference_delta_e_lit)},
                                  {"path_delta_e_driest_wettest_shaded", cell(p.reference_delta_e_shaded)},
                                  {"wall_s", cell(seconds_since(start))}}));
  std::printf("figure 13: shaded/lit %.3f -> %.3f (CDRF), %.3f -> %.3f (random walk); CDRF %.1f s, reference %.1f s "
              "bake + %.1f s render; worst per-grain RMS difference %.0f%%\n",
              m.shaded.front() / m.lit.front(), m.shaded.back() / m.lit.back(),
              m.reference_shaded.front() / m.reference_lit.front(), m.reference_shaded.back() / m.reference_lit.back(),
              cdrf_stats.seconds, bake_stats.seconds, reference_stats.seconds, 100 * m.worst_relative);
  std::printf("figure 13: driest against wettest grain, Delta E*ab lit %.1f, shaded %.1f (CDRF); lit %.1f, shaded %.1f "
              "(random walk); lit %.1f, shaded %.1f (path traced, %.1f s); the CDRF differs from the path tracer by up "
              "to %.0f%% RMS per grain\n",
              m.delta_e_lit, m.delta_e_shaded, m.reference_delta_e_lit, m.reference_delta_e_shaded,
              p.reference_delta_e_lit, p.reference_delta_e_shaded, path_stats.seconds, 100 * p.worst_relative);
}

}  // namespace rice::experiments
