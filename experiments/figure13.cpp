// Figure 13 driver; see figure13.hpp.
#include "experiments/figure13.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "experiments/gnuplot.hpp"
#include "experiments/interrupt.hpp"
#include "experiments/output.hpp"
#include "experiments/render_command.hpp"
#include "experiments/render_output.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"
#include "grains/water_content.hpp"

namespace rice::experiments {

void validate(const Figure13Settings& s) {
  if (s.soak_minutes.empty() || s.soak_minutes.size() > 12)
    throw std::invalid_argument("figure 13: give 1 to 12 --soak-minutes");
  for (const double t : s.soak_minutes)
    if (!(t > 0.0 && t <= 10000.0)) throw std::invalid_argument("figure 13: --soak-minutes must be in (0, 10000]");
  if (s.width < 16 || s.height < 16 || s.width > 16384 || s.height > 16384)
    throw std::invalid_argument("figure 13: --width and --height must be in [16, 16384]");
  if (s.samples_per_pixel < 1 || s.samples_per_pixel > 1 << 20)
    throw std::invalid_argument("figure 13: --spp must be in [1, 1048576]");
}

void figure13_command(const Figure13Settings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  const grains::WaterContentModel model(grains::read_absorption_table(grains::default_absorption_table()));
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  const grains::Grain grain = grains::make_grain(recipe, settings.seed, 1.0);
  make_output_folder(folder);

  // One grain, lying flat, repeated along x: only the water content differs between them.
  shading::RenderScene scene;
  const int prototype = add_grain_prototype(scene, grain.render.V, grain.render.F);
  const Eigen::Vector3d lo = grain.render.V.colwise().minCoeff(), hi = grain.render.V.colwise().maxCoeff();
  const double pitch = 1.25 * (hi.x() - lo.x());
  const int n = static_cast<int>(settings.soak_minutes.size());
  std::vector<shading::Material> materials;
  std::vector<double> absorption;
  for (int i = 0; i < n; ++i) {
    absorption.push_back(model.absorption_percent(settings.soak_minutes[i], settings.temperature_c));
    materials.push_back(rice_material(absorption.back()));
    Eigen::Affine3d place = Eigen::Affine3d::Identity();
    place.translation() = Eigen::Vector3d(i * pitch - 0.5 * (lo.x() + hi.x()), -0.5 * (lo.y() + hi.y()), -lo.z());
    scene.add_instance(prototype, place, i);
  }
  materials.push_back({.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color::Constant(0.05f)});
  {
    const double half = n * pitch;
    shading::MeshVertices V(4, 3);
    V << -half, -half, 0, 2 * half, -half, 0, 2 * half, half, 0, -half, half, 0;
    shading::MeshTriangles F(2, 3);
    F << 0, 1, 2, 0, 2, 3;
    scene.add_instance(scene.add_prototype(V, F), Eigen::Affine3d::Identity(), n);  // dark cloth
  }
  scene.commit();

  // The sun high behind the row, a dim sky; the camera looks at the row from the front, so
  // each grain shows its lit top, its terminator and its shaded front.
  shading::Lights lights;
  lights.suns.push_back({.direction = Eigen::Vector3f(0.0f, 0.6f, 0.8f), .irradiance = shading::Color::Constant(4.0f)});
  lights.environment.constant = shading::Color::Constant(0.15f);
  const double aspect = static_cast<double>(settings.width) / settings.height;
  // The row, n pitches wide, fills the image's width, seen from 25° above the front.
  shading::Camera camera;
  camera.vertical_fov_degrees = 10.0;
  camera.target = Eigen::Vector3d(0.5 * (n - 1) * pitch, 0.0, 0.5 * (hi.z() - lo.z()));
  const double half_width = std::tan(0.5 * camera.vertical_fov_degrees * std::numbers::pi / 180.0) * aspect;
  const double distance = 0.5 * n * pitch / half_width;
  const double elevation = 25.0 * std::numbers::pi / 180.0;
  camera.position = camera.target + distance * Eigen::Vector3d(0.0, -std::cos(elevation), std::sin(elevation));

  const shading::CdrfTable cdrf(513, 513);
  shading::RenderSettings render{.width = settings.width, .height = settings.height,
                                 .samples_per_pixel = settings.samples_per_pixel, .seed = settings.seed};
  shading::RenderStats stats;
  Progress progress("figure 13: tiles", shading::tile_count(render));
  const shading::Image image = shading::render(scene, materials, lights, camera, cdrf, render, &stats,
                                               [&](int done, int) { progress.update(done); }, stop_requested);
  progress.finish();
  stop_point();

  // Each grain's mean radiance on the sun's side and on the far side, from the pixels whose
  // centre ray hits it.
  std::vector<double> lit(n, 0.0), shaded(n, 0.0);
  std::vector<int> lit_count(n, 0), shaded_count(n, 0);
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      const shading::CameraRay r = camera.ray((x + 0.5) / settings.width, (y + 0.5) / settings.height, 0, 0, aspect);
      const auto hit = scene.intersect({r.origin, r.direction});
      if (!hit || hit->instance >= n) continue;
      const bool sunny = hit->shading_normal.dot(lights.suns[0].direction.normalized()) > 0.0f;
      (sunny ? lit : shaded)[hit->instance] += image.at(x, y).mean();
      ++(sunny ? lit_count : shaded_count)[hit->instance];
    }
  CsvTable table({"soak_minutes", "absorption_percent", "sigma0_mm", "albedo", "lit_radiance", "shaded_radiance",
                  "shaded_over_lit"});
  for (int i = 0; i < n; ++i) {
    lit[i] /= std::max(1, lit_count[i]);
    shaded[i] /= std::max(1, shaded_count[i]);
    table.add_row({cell(settings.soak_minutes[i]), cell(absorption[i]), cell(1e3 * materials[i].sigma0),
                   cell(static_cast<double>(materials[i].albedo[0])), cell(lit[i]), cell(shaded[i]),
                   cell(shaded[i] / lit[i])});
  }
  write_file_atomically(folder / "figure13.csv", table.text());
  write_png(folder / "figure13_render.png", tone_map(image, 0.0));
  write_exr(folder / "figure13_render.exr", image);

  std::string labels;
  for (int i = 0; i < n; ++i) {
    labels += "set label " + std::to_string(i + 1) + " '" + fixed(settings.soak_minutes[i], 0) + " min, W = " +
              fixed(absorption[i], 1) + "%' at graph " + fixed((i + 0.5) / n, 3) + ", 0.08 center front tc rgb 'white'\n";
  }
  render_plot(folder, "figure13", "set terminal pngcairo size " + std::to_string(settings.width) + "," +
                                      std::to_string(settings.height + 60) + R"(
set output 'figure13.png'
set title 'Soaked longer at )" + fixed(settings.temperature_c, 0) + R"( °C, grains scatter wider: shaded/lit radiance )" +
                                      fixed(shaded.front() / lit.front(), 2) + " → " + fixed(shaded.back() / lit.back(), 2) + R"('
unset border
unset tics
unset key
set margins 0, 0, 0, 4
set xrange [0:)" + std::to_string(settings.width - 1) + R"(]
set yrange [0:)" + std::to_string(settings.height - 1) + R"(]
)" + labels + R"(plot 'figure13_render.png' binary filetype=png with rgbimage
)");
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"figure", "13"},
                                  {"temperature_c", cell(settings.temperature_c)},
                                  {"width", cell(settings.width)},
                                  {"height", cell(settings.height)},
                                  {"samples_per_pixel", cell(settings.samples_per_pixel)},
                                  {"seed", cell(static_cast<long>(settings.seed))},
                                  {"render_s", cell(stats.seconds)},
                                  {"wall_s", cell(seconds_since(start))}}));
  std::printf("figure 13: shaded/lit radiance %.3f at %.0f min to %.3f at %.0f min\n", shaded.front() / lit.front(),
              settings.soak_minutes.front(), shaded.back() / lit.back(), settings.soak_minutes.back());
}

}  // namespace rice::experiments
