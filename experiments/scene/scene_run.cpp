// `rice run`; see scene_run.hpp.
#include "experiments/scene/scene_run.hpp"

#include <chrono>
#include <cstdio>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/progress.hpp"
#include "grains/absorption_table.hpp"
#include "grains/water_content.hpp"

namespace rice::experiments {

RenderCommandSettings scene_render_settings(const SceneRender& r, const PourSettings& pour,
                                            const std::filesystem::path& run) {
  RenderCommandSettings s;
  s.pour = run;
  const grains::WaterContentModel water(grains::read_absorption_table(grains::default_absorption_table()));
  s.absorption_percent = water.absorption_percent(pour.soak_minutes, pour.soak_temperature);
  s.render.width = r.width;
  s.render.height = r.height;
  s.render.samples_per_pixel = r.samples_per_pixel;
  s.sun_elevation_degrees = r.sun_elevation_degrees;
  s.sun_azimuth_degrees = r.sun_azimuth_degrees;
  s.sun_irradiance = r.sun_irradiance;
  s.sky_radiance = r.sky_radiance;
  s.ground = r.ground;
  if (r.eye) {
    shading::Camera camera;
    camera.position = *r.eye;
    camera.target = *r.look_at;
    camera.vertical_fov_degrees = r.vertical_fov_degrees;
    s.camera = camera;
  }
  return s;
}

SceneResult run_scene_command(const std::filesystem::path& scene_file, const std::vector<std::string>& overrides,
                             const std::filesystem::path& folder) {
  const std::string text = read_scene_text(scene_file);
  const SceneDescription scene = parse_scene(text, scene_file.string(), overrides);
  validate(scene.pour);
  make_output_folder(folder);
  std::string copy = text;
  if (!overrides.empty()) {
    copy += "\n# overridden on the command line (rice run --set):\n";
    for (const std::string& o : overrides) copy += "#   " + o + "\n";
  }
  write_file_atomically(folder / "scene.toml", copy);
  std::printf("scene %s: %s\n", scene.name.c_str(), scene.description.c_str());
  SceneResult result;
  result.pour = pour_command(scene.pour, folder);
  if (scene.render) {
    const auto start = std::chrono::steady_clock::now();
    RenderCommandSettings settings = scene_render_settings(*scene.render, scene.pour, folder);
    settings.camera = render_command(settings, folder / "render");
    result.render_seconds = seconds_since(start);
    if (scene.render->every_frame) {
      settings.every_frame = true;
      render_command(settings, folder / "render_frames");
    }
  }
  return result;
}

}  // namespace rice::experiments
