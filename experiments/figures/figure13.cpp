// Figure 13 driver; see figure13.hpp.
#include "experiments/figures/figure13.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/render_images.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "experiments/render/translucency_tables.hpp"
#include "grains/absorption_table.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"
#include "grains/water_content.hpp"
#include "shading/cielab.hpp"
#include "shading/path_tracer.hpp"
#include "shading/renderer.hpp"

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

/// What every image of the row shares besides its materials.
struct RowView {
  const shading::Lights& lights;
  const shading::Camera& camera;
  const shading::CdrfTable& cdrf;
  const Figure13Settings& settings;
};

/// One row of the figure: its image and the seconds it took.
struct RowImage {
  std::string name;  // cdrf, translucent, path
  shading::Image image;
  double seconds = 0.0;
};

/// The paper's CDRF, direct light.
RowImage render_cdrf_row(const GrainRow& row, const RowView& view) {
  Progress progress("figure 13: CDRF tiles", shading::tile_count(view.settings.width, view.settings.height));
  shading::RenderStats stats;
  const shading::RenderSettings render{.width = view.settings.width, .height = view.settings.height,
                                       .samples_per_pixel = view.settings.samples_per_pixel, .seed = view.settings.seed};
  shading::Image image = shading::render(row.scene, row.materials, view.lights, view.camera, view.cdrf, render, &stats,
                                         [&](int done, int) { progress.update(done); }, stop_requested);
  progress.finish();
  stop_point();
  return {"cdrf", std::move(image), stats.seconds};
}

/// The translucent model (the CDRF and τ at each grain's W) with its bounces between grains
/// and the cloth, by the path tracer's fast model; or the reference: each grain its own
/// medium, the cloth Lambertian.
RowImage render_path_row(const GrainRow& row, const RowView& view, bool reference) {
  std::vector<shading::Material> materials = row.materials;
  std::vector<std::optional<shading::Medium>> media;
  for (int i = 0; i < row.n; ++i) {
    if (reference) media.push_back(grain_medium(row.absorption[i]));
    else materials[i] = translucent_rice_material(row.absorption[i]);
  }
  const Figure13Settings& s = view.settings;
  shading::PathTraceSettings settings{.width = s.width, .height = s.height,
                                      .samples_per_pixel = reference ? s.path_spp : s.samples_per_pixel, .seed = s.seed};
  if (!reference) {
    settings.max_depth = 1 + s.translucent_bounces;
    settings.cdrf = &view.cdrf;
  }
  const std::string name = reference ? "path" : "translucent";
  Progress progress("figure 13: " + name + " tiles", shading::tile_count(s.width, s.height));
  shading::PathTraceStats stats;
  shading::Image image = shading::path_trace(row.scene, materials, media, view.lights, view.camera, settings, &stats,
                                             [&](int done, int) { progress.update(done); }, stop_requested);
  progress.finish();
  stop_point();
  return {name, std::move(image), stats.seconds};
}

/// Per grain, from the pixels whose centre ray hits it: the mean radiance of its sun side and
/// its far side, and its RMS difference from the reference over its mean there; and how
/// visibly the driest and the wettest grain differ, ΔE*ab of their sides' mean displayed
/// colours (after the tone curve).
struct RowMeasure {
  std::vector<double> lit, shaded, relative_rms;
  double worst_relative = 0.0;  ///< the largest relative_rms
  double delta_e_lit = 0.0, delta_e_shaded = 0.0;
};

Eigen::Vector3d tone_curve(const shading::Color& radiance) {
  return {aces_filmic(radiance[0]), aces_filmic(radiance[1]), aces_filmic(radiance[2])};
}

RowMeasure measure_row(const GrainRow& row, const shading::Image& image, const shading::Image& reference,
                       const RowView& view) {
  const int n = row.n, width = view.settings.width, height = view.settings.height;
  const double aspect = static_cast<double>(width) / height;
  RowMeasure m;
  m.lit.assign(n, 0.0);
  m.shaded = m.relative_rms = m.lit;
  std::vector<double> squared(n, 0.0), sum(n, 0.0);
  std::vector<int> count[2] = {std::vector<int>(n, 0), std::vector<int>(n, 0)};  // lit, shaded
  std::vector<Eigen::Vector3d> shown[2] = {std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero()),
                                           std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero())};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const shading::CameraRay r = view.camera.ray((x + 0.5) / width, (y + 0.5) / height, 0, 0, aspect);
      const auto hit = row.scene.intersect({r.origin, r.direction});
      if (!hit || hit->instance >= n) continue;
      const int g = hit->instance;
      const int side = hit->shading_normal.dot(view.lights.suns[0].direction.normalized()) > 0.0f ? 0 : 1;
      (side == 0 ? m.lit : m.shaded)[g] += image.at(x, y).mean();
      ++count[side][g];
      shown[side][g] += tone_curve(image.at(x, y));
      sum[g] += reference.at(x, y).mean();
      squared[g] += (image.at(x, y) - reference.at(x, y)).square().mean();
    }
  for (int i = 0; i < n; ++i) {
    const int pixels = std::max(1, count[0][i] + count[1][i]);
    m.lit[i] /= std::max(1, count[0][i]);
    m.shaded[i] /= std::max(1, count[1][i]);
    m.relative_rms[i] = std::sqrt(squared[i] / pixels) / (sum[i] / pixels);
    m.worst_relative = std::max(m.worst_relative, m.relative_rms[i]);
  }
  const auto delta_e = [&](int side) {
    const auto shown_mean = [&](int g) { return Eigen::Vector3d(shown[side][g] / std::max(1, count[side][g])); };
    return shading::delta_e76(shown_mean(0), shown_mean(n - 1));
  };
  m.delta_e_lit = delta_e(0);
  m.delta_e_shaded = delta_e(1);
  return m;
}

/// A row per grain: for each image row, its lit and shaded radiance, their ratio and its
/// relative RMS difference from the path-traced reference.
CsvTable figure13_table(const Figure13Settings& settings, const GrainRow& row, const std::vector<RowImage>& rows,
                        const std::vector<RowMeasure>& measures) {
  std::vector<std::string> header = {"soak_minutes", "absorption_percent", "sigma0_mm", "albedo"};
  for (const RowImage& r : rows)
    for (const char* column : {"_lit_radiance", "_shaded_radiance", "_shaded_over_lit", "_relative_rms_from_path"})
      header.push_back(r.name + column);
  CsvTable table(header);
  for (int i = 0; i < row.n; ++i) {
    std::vector<std::string> cells = {cell(settings.soak_minutes[i]), cell(row.absorption[i]),
                                      cell(1e3 * row.materials[i].sigma0), cell(static_cast<double>(row.materials[i].albedo[0]))};
    for (const RowMeasure& m : measures)
      cells.insert(cells.end(), {cell(m.lit[i]), cell(m.shaded[i]), cell(m.shaded[i] / m.lit[i]), cell(m.relative_rms[i])});
    table.add_row(cells);
  }
  return table;
}

std::string ratio_span(const RowMeasure& m) {
  return fixed(m.shaded.front() / m.lit.front(), 2) + " → " + fixed(m.shaded.back() / m.lit.back(), 2);
}

/// figure13.png: the three rows, labelled with each grain's soak and W.
void plot_figure13(const std::filesystem::path& folder, const Figure13Settings& settings, const GrainRow& row,
                   const std::vector<RowMeasure>& m) {
  const int n = row.n;
  std::string labels;
  for (int i = 0; i < n; ++i) {
    labels += "set label " + std::to_string(i + 1) + " '" + fixed(settings.soak_minutes[i], 0) + " min, W = " +
              fixed(row.absorption[i], 1) + "%' at graph " + fixed((i + 0.5) / n, 3) + ", 0.08 center front tc rgb 'white'\n";
  }
  const std::string size = std::to_string(settings.width) + "," + std::to_string(3 * settings.height + 100);
  const std::string range = "set xrange [0:" + std::to_string(settings.width - 1) + "]\nset yrange [0:" +
                            std::to_string(settings.height - 1) + "]\n";
  const auto rms = [](const RowMeasure& r) { return " (up to " + fixed(100 * r.worst_relative, 0) + "% RMS per grain from the path tracer)"; };
  render_plot(folder, "figure13", "set terminal pngcairo size " + size + R"(
set output 'figure13.png'
set multiplot layout 3,1 title 'Soaked longer at )" + fixed(settings.temperature_c, 0) + " °C, shaded/lit " +
                                      ratio_span(m[0]) + " (CDRF), " + ratio_span(m[1]) + " (translucent), " +
                                      ratio_span(m[2]) + R"( (path traced)'
unset border
unset tics
unset key
set margins 0, 0, 0, 3
)" + range + labels + "set title 'the CDRF of the paper" + rms(m[0]) + R"('
plot 'figure13_cdrf.png' binary filetype=png with rgbimage
set title 'translucent model, )" + std::to_string(settings.translucent_bounces) + " bounce(s)" + rms(m[1]) + R"('
plot 'figure13_translucent.png' binary filetype=png with rgbimage
set title 'path traced, the reference'
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
  if (s.translucent_bounces < 0 || s.translucent_bounces > 16)
    throw std::invalid_argument("figure 13: --translucent-bounces must be in [0, 16]");
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
  const RowView view{lights, camera, cdrf, settings};
  const std::vector<RowImage> rows = {render_cdrf_row(row, view), render_path_row(row, view, false),
                                      render_path_row(row, view, true)};
  std::vector<RowMeasure> measures;
  for (const RowImage& r : rows) measures.push_back(measure_row(row, r.image, rows.back().image, view));

  write_file_atomically(folder / "figure13.csv", figure13_table(settings, row, rows, measures).text());
  for (const RowImage& r : rows) {
    write_png(folder / ("figure13_" + r.name + ".png"), tone_map(r.image, 0.0));
    write_exr(folder / ("figure13_" + r.name + ".exr"), r.image);
  }
  plot_figure13(folder, settings, row, measures);
  std::vector<std::pair<std::string, std::string>> info = {{"figure", "13"},
                                                           {"temperature_c", cell(settings.temperature_c)},
                                                           {"width", cell(settings.width)},
                                                           {"height", cell(settings.height)},
                                                           {"samples_per_pixel", cell(settings.samples_per_pixel)},
                                                           {"path_spp", cell(settings.path_spp)},
                                                           {"translucent_bounces", cell(settings.translucent_bounces)},
                                                           {"seed", cell(static_cast<long>(settings.seed))}};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::string& name = rows[k].name;
    const RowMeasure& m = measures[k];
    info.insert(info.end(), {{name + "_render_s", cell(rows[k].seconds)},
                             {name + "_worst_relative_rms_from_path", cell(m.worst_relative)},
                             {name + "_delta_e_driest_wettest_lit", cell(m.delta_e_lit)},
                             {name + "_delta_e_driest_wettest_shaded", cell(m.delta_e_shaded)}});
    std::printf("figure 13: %s: %.1f s, shaded/lit %.3f -> %.3f, Delta E*ab driest/wettest lit %.1f, shaded %.1f, up "
                "to %.0f%% RMS per grain from the path tracer\n",
                name.c_str(), rows[k].seconds, m.shaded.front() / m.lit.front(), m.shaded.back() / m.lit.back(),
                m.delta_e_lit, m.delta_e_shaded, 100 * m.worst_relative);
  }
  info.emplace_back("wall_s", cell(seconds_since(start)));
  write_file_atomically(folder / "run_info.txt", run_info(info));
}

}  // namespace rice::experiments
