// A scene run; see scene_run.hpp.
#include "experiments/scene/scene_run.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/content_digest.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/peak_memory.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/scene/checkpoint.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_parts.hpp"
#include "experiments/scene/stepper.hpp"
#include "experiments/scene/world_builder.hpp"
#include "grains/absorption_table.hpp"
#include "grains/water_content.hpp"

namespace rice::experiments {
namespace {

using Observers = std::vector<std::unique_ptr<Observer>>;

/// "fewest-most" vertices over the variants' simulation meshes.
std::string mesh_vertex_range(const World& world) {
  long fewest = 0, most = 0;
  for (const GrainVariant& v : world.variants) {
    const long n = v.grain.simulation.V.rows();
    fewest = fewest == 0 ? n : std::min(fewest, n);
    most = std::max(most, n);
  }
  return std::to_string(fewest) + "-" + std::to_string(most);
}

/// The scene's settings as it ran them, for run_info.txt.
RunInfoEntries scene_entries(const Scene& scene, const World& world) {
  const bool plate = scene.container.kind == Container::kPlate;
  const bool rigid = scene.grains.body == xpbd::BodyKind::kRigid;
  return {{"command", "run"},
          {"scene", scene.name},
          {"container", plate ? "plate" : "chawan"},
          {"chawan_scale", cell(scene.container.scale)},
          {"rim_height_m", plate ? "n/a" : cell(world.bowl.height)},
          {"more_colliders", cell(static_cast<long>(scene.colliders.size() + scene.mesh_colliders.size()))},
          {"cultivar", scene.grains.cultivar},
          {"count", cell(scene.grains.count)},
          {"variants", cell(scene.grains.variants)},
          {"body", rigid ? "rigid" : "soft"},
          {"frames", cell(scene.solver.frames)},
          {"fps", cell(scene.solver.fps)},
          {"radius_interval_s", cell(scene.solver.radius_interval)},
          {"young_pa", cell(scene.grains.young)},
          {"mesh_vertices", mesh_vertex_range(world)},
          {"vertex_mass_floor", rigid ? "n/a" : cell(scene.grains.vertex_mass_floor)},
          {"rayleigh_time_s", cell(world.rayleigh_time)},
          {"cohesion", scene.effects.cohesion ? "on" : "off"},
          {"damping", scene.effects.damping ? "on" : "off"},
          {"pull_off_force_in_weights", cell(world.pull_off_in_weights)},
          {"bond_heal_s", cell(world.model.contact.bond_heal_time)},
          {"sleeping", scene.effects.sleeping ? "on" : "off"},
          {"sleep_speed_m_s", cell(scene.effects.sleep_speed)},
          {"sleep_frames", cell(scene.effects.sleep_frames)},
          {"static_friction", cell(scene.effects.static_friction)},
          {"dynamic_friction", cell(scene.effects.dynamic_friction)},
          {"seed", std::to_string(scene.grains.seed)},
          {"frame_poses", rigid ? "world = q (p0 - c0) + (x, y, z); c0 the grain's first centre" : "simulation vertices"}};
}

/// Every frame from `first`: the emitter releases what is due, the stepper steps, the
/// observers look; a checkpoint when one is due and on Ctrl-C or SIGTERM (then Interrupted).
/// Returns the wall time.
double step_frames(const Scene& scene, int first, const RunParts& parts, const std::filesystem::path& folder,
                   std::uint64_t scene_digest) {
  const int frames = scene.solver.frames;
  Progress progress("scene frames", frames, 30.0, first - 1);
  CheckpointClock checkpoints(scene.solver.checkpoint_every);
  const auto start = std::chrono::steady_clock::now();
  for (int frame = first; frame <= frames; ++frame) {
    const auto frame_start = std::chrono::steady_clock::now();
    parts.emitter.emit(parts.world, parts.stepper.time());
    parts.stepper.step();
    const double wall = seconds_since(frame_start);
    for (auto& observer : parts.observers) observer->observe(parts.world, parts.stepper, frame, wall);
    progress.update(frame);
    const bool stopping = stop_requested();
    if (stopping || (frame < frames && checkpoints.due(frame))) write_checkpoint(folder, scene_digest, frame, parts);
    if (stopping) stop_point();
  }
  progress.finish();
  return seconds_since(start);
}

void print_summary(const Scene& scene, const Stepper& stepper, double simulation_seconds, double setup_seconds) {
  const xpbd::SolverTimings& t = stepper.timings();
  std::cout << "rice run: " << scene.grains.count << (scene.grains.body == xpbd::BodyKind::kRigid ? " rigid" : " soft")
            << " grains, " << scene.solver.frames << " frames in " << simulation_seconds << " s (broad phase "
            << t.broad_phase << " s, narrow phase " << t.narrow_phase << " s, solves " << t.solve() << " s, sleeping "
            << t.sleeping << " s); set-up " << setup_seconds << " s\n";
}

}  // namespace

SceneRun::SceneRun(const Scene& scene) : scene_(scene), start_(std::chrono::steady_clock::now()) {
  validate(scene_);
  emitter_ = make_emitter(scene_);
  world_ = build_world(scene_, *emitter_);
}

SceneRun::~SceneRun() = default;

SceneResult SceneRun::run(const std::filesystem::path& folder, const RunStart& run_start) {
  make_output_folder(folder);
  Observers observers = make_observers(scene_, folder);
  for (auto& observer : observers) observer->begin(world_);
  Stepper stepper(world_.model, scene_);
  const RunParts parts{world_, *emitter_, stepper, observers};
  int first = 1;
  if (run_start.resume) {
    first = resume_from_checkpoint(folder, run_start.scene_digest, parts) + 1;
    std::printf("rice run: resumed after frame %d\n", first - 1);
  }
  const double setup_seconds = seconds_since(start_);
  const double simulation_seconds = step_frames(scene_, first, parts, folder, run_start.scene_digest);

  SceneReport report;
  report.result.simulation_seconds = simulation_seconds;
  report.info = scene_entries(scene_, world_);
  emitter_->report(world_, report.info);
  stepper.report(report.info);
  for (auto& observer : observers) observer->end(world_, stepper, report);
  stop_point();
  print_summary(scene_, stepper, simulation_seconds, setup_seconds);
  report.info.push_back({"setup_wall_s", cell(setup_seconds)});
  report.info.push_back({"simulation_wall_s", cell(simulation_seconds)});
  report.info.push_back({"peak_memory_mib", cell(peak_resident_mib())});  // before any render
  report.info.push_back({"wall_s", cell(seconds_since(start_))});
  write_file_atomically(folder / "run_info.txt", run_info(report.info));
  std::filesystem::remove(checkpoint_path(folder));  // the run is complete
  return report.result;
}

SceneResult run_scene(const Scene& scene, const std::filesystem::path& folder) { return SceneRun(scene).run(folder); }

RenderCommandSettings scene_render_settings(const SceneRender& r, const Scene& scene, const std::filesystem::path& run) {
  RenderCommandSettings s;
  s.run = run;
  const grains::WaterContentModel water(grains::read_absorption_table(grains::default_absorption_table()));
  s.absorption_percent = water.absorption_percent(scene.grains.soak_minutes, scene.grains.soak_temperature);
  s.render.width = r.width;
  s.render.height = r.height;
  s.render.samples_per_pixel = r.samples_per_pixel;
  s.integrator = r.integrator == "path"          ? RenderIntegrator::kPath
                 : r.integrator == "translucent" ? RenderIntegrator::kTranslucent
                                                 : RenderIntegrator::kCdrf;
  s.bounces = r.bounces;
  s.lighting = r.studio ? Lighting::kStudio : Lighting::kSun;
  s.studio.key_irradiance = r.key_irradiance;
  s.studio.fill_ratio = r.fill_ratio;
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
                              const std::filesystem::path& folder, const RunCommandOptions& options) {
  const std::string text = read_scene_text(scene_file);
  const Scene scene = parse_scene(text, scene_file.string(), overrides);
  SceneRun run(scene);  // nothing written before the scene is known to run
  make_output_folder(folder);
  std::string copy = text;
  if (!overrides.empty()) {
    copy += "\n# overridden on the command line (rice run --set):\n";
    for (const std::string& o : overrides) copy += "#   " + o + "\n";
  }
  write_file_atomically(folder / "scene.toml", copy);
  std::printf("scene %s: %s\n", scene.name.c_str(), scene.description.c_str());
  SceneResult result = run.run(folder, {options.resume, content_digest(copy)});
  if (scene.render && options.render) {
    const auto start = std::chrono::steady_clock::now();
    RenderCommandSettings settings = scene_render_settings(*scene.render, scene, folder);
    const bool every_frame = scene.render->every_frame || scene.render->video;
    if (every_frame)  // two renders of one run: the variants' curvature smoothed once
      settings.variants = std::make_shared<const RunVariants>(read_run_variants(folder, settings.shading_radius));
    render_command(settings, folder / "render");
    result.render_seconds = seconds_since(start);
    if (every_frame) {  // framed on what any frame shows
      settings.every_frame = true;
      settings.video = scene.render->video;
      render_command(settings, folder / "render_frames");
    }
  }
  return result;
}

}  // namespace rice::experiments
