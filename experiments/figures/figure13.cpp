// Figure 13 driver; see figure13.hpp.
#include "experiments/figures/figure13.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "shading/renderer.hpp"
#include "experiments/io/render_images.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"
#include "grains/water_content.hpp"
#include "shading/subsurface_bake.hpp"

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
  if (s.photons < 1000 || s.photons > 1'000'000'000LL)
    throw std::invalid_argument("figure 13: --photons must be in [1000, 1e9]");
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
  add_ground(scene, -n * pitch, -n * pitch, 2 * n * pitch, n * pitch, 0.0, n);  // a dark cloth
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
  const shading::RenderSettings render{.width = settings.width, .height = settings.height,
                                       .samples_per_pixel = settings.samples_per_pixel, .seed = settings.seed};
  auto render_row = [&](const std::vector<shading::Material>& row_materials, const std::string& label,
                        shading::RenderStats& stats) {
    Progress progress("figure 13: " + label + " tiles", shading::tile_count(render));
    shading::Image image = shading::render(scene, row_materials, lights, camera, cdrf, render, &stats,
                                           [&](int done, int) { progress.update(done); }, stop_requested);
    progress.finish();
    stop_point();
    return image;
  };
  shading::RenderStats cdrf_stats, reference_stats;
  const shading::Image image = render_row(materials, "CDRF", cdrf_stats);

  // The reference: each grain's subsurface light baked by the random walk in its own medium.
  std::vector<int> grain_instances(n);
  std::vector<shading::Medium> media;
  std::vector<shading::Material> reference_materials = materials;
  for (int i = 0; i < n; ++i) {
    grain_instances[i] = i;
    media.push_back(grain_medium(absorption[i]));
    reference_materials[i].kind = shading::MaterialKind::kSubsurfaceReference;
  }
  shading::BakeStats bake_stats;
  {
    Progress progress("figure 13: random-walk bake", 1);
    shading::bake_subsurface(scene, grain_instances, media, lights,
                             {.photons_per_light = settings.photons, .seed = settings.seed}, &bake_stats);
    progress.finish();
  }
  stop_point();
  const shading::Image reference = render_row(reference_materials, "reference", reference_stats);

  // Per grain, from the pixels whose centre ray hits it: mean radiance on the sun's side and
  // on the far side, in both images, and the RMS difference between them.
  std::vector<double> lit(n, 0.0), shaded(n, 0.0), reference_lit(n, 0.0), reference_shaded(n, 0.0), squared(n, 0.0);
  std::vector<int> lit_count(n, 0), shaded_count(n, 0);
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      const shading::CameraRay r = camera.ray((x + 0.5) / settings.width, (y + 0.5) / settings.height, 0, 0, aspect);
      const auto hit = scene.intersect({r.origin, r.direction});
      if (!hit || hit->instance >= n) continue;
      const int g = hit->instance;
      const bool sunny = hit->shading_normal.dot(lights.suns[0].direction.normalized()) > 0.0f;
      (sunny ? lit : shaded)[g] += image.at(x, y).mean();
      (sunny ? reference_lit : reference_shaded)[g] += reference.at(x, y).mean();
      ++(sunny ? lit_count : shaded_count)[g];
      squared[g] += (image.at(x, y) - reference.at(x, y)).square().mean();
    }
  CsvTable table({"soak_minutes", "absorption_percent", "sigma0_mm", "albedo", "lit_radiance", "shaded_radiance",
                  "shaded_over_lit", "reference_lit_radiance", "reference_shaded_radiance", "reference_shaded_over_lit",
                  "rms_difference", "relative_rms_difference"});
  double worst_relative = 0.0;
  for (int i = 0; i < n; ++i) {
    const int pixels = std::max(1, lit_count[i] + shaded_count[i]);
    const double mean = (lit[i] + shaded[i]) / pixels;
    lit[i] /= std::max(1, lit_count[i]);
    shaded[i] /= std::max(1, shaded_count[i]);
    reference_lit[i] /= std::max(1, lit_count[i]);
    reference_shaded[i] /= std::max(1, shaded_count[i]);
    const double rms = std::sqrt(squared[i] / pixels);
    worst_relative = std::max(worst_relative, rms / mean);
    table.add_row({cell(settings.soak_minutes[i]), cell(absorption[i]), cell(1e3 * materials[i].sigma0),
                   cell(static_cast<double>(materials[i].albedo[0])), cell(lit[i]), cell(shaded[i]),
                   cell(shaded[i] / lit[i]), cell(reference_lit[i]), cell(reference_shaded[i]),
                   cell(reference_shaded[i] / reference_lit[i]), cell(rms), cell(rms / mean)});
  }
  write_file_atomically(folder / "figure13.csv", table.text());
  write_png(folder / "figure13_render.png", tone_map(image, 0.0));
  write_exr(folder / "figure13_render.exr", image);
  write_png(folder / "figure13_reference.png", tone_map(reference, 0.0));
  write_exr(folder / "figure13_reference.exr", reference);

  std::string labels;
  for (int i = 0; i < n; ++i) {
    labels += "set label " + std::to_string(i + 1) + " '" + fixed(settings.soak_minutes[i], 0) + " min, W = " +
              fixed(absorption[i], 1) + "%' at graph " + fixed((i + 0.5) / n, 3) + ", 0.08 center front tc rgb 'white'\n";
  }
  const std::string size = std::to_string(settings.width) + "," + std::to_string(2 * settings.height + 80);
  const std::string range = "set xrange [0:" + std::to_string(settings.width - 1) + "]\nset yrange [0:" +
                            std::to_string(settings.height - 1) + "]\n";
  render_plot(folder, "figure13", "set terminal pngcairo size " + size + R"(
set output 'figure13.png'
set multiplot layout 2,1 title 'Soaked longer at )" + fixed(settings.temperature_c, 0) +
                                      R"( °C, grains scatter wider: shaded/lit )" + fixed(shaded.front() / lit.front(), 2) +
                                      " → " + fixed(shaded.back() / lit.back(), 2) + " (CDRF), " +
                                      fixed(reference_shaded.front() / reference_lit.front(), 2) + " → " +
                                      fixed(reference_shaded.back() / reference_lit.back(), 2) + R"( (random walk)'
unset border
unset tics
unset key
set margins 0, 0, 0, 3
)" + range + labels + R"(set title 'CDRF'
plot 'figure13_render.png' binary filetype=png with rgbimage
set title 'random-walk reference (CDRF differs by up to )" + fixed(100 * worst_relative, 0) + R"(% RMS per grain)'
plot 'figure13_reference.png' binary filetype=png with rgbimage
unset multiplot
)");
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
                                  {"worst_relative_rms_difference", cell(worst_relative)},
                                  {"wall_s", cell(seconds_since(start))}}));
  std::printf("figure 13: shaded/lit %.3f -> %.3f (CDRF), %.3f -> %.3f (random walk); CDRF %.1f s, reference %.1f s "
              "bake + %.1f s render; worst per-grain RMS difference %.0f%%\n",
              shaded.front() / lit.front(), shaded.back() / lit.back(), reference_shaded.front() / reference_lit.front(),
              reference_shaded.back() / reference_lit.back(), cdrf_stats.seconds, bake_stats.seconds,
              reference_stats.seconds, 100 * worst_relative);
}

}  // namespace rice::experiments
