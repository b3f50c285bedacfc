// `rice render`; see render_command.hpp.
#include "experiments/render/render_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/render_images.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/io/video.hpp"
#include "experiments/render/framing_box.hpp"
#include "experiments/render/render_stage.hpp"
#include "experiments/render/run_frames.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "grains/mesh_io.hpp"
#include "shading/path_tracer.hpp"

namespace rice::experiments {
namespace {

std::vector<std::filesystem::path> mesh_files(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::filesystem::path> files;
  for (const auto& input : inputs) {
    if (std::filesystem::is_directory(input)) {
      std::vector<std::filesystem::path> found;
      for (const auto& entry : std::filesystem::directory_iterator(input)) {
        const auto ext = entry.path().extension();
        if (entry.is_regular_file() && (ext == ".ply" || ext == ".obj")) found.push_back(entry.path());
      }
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.push_back(input);
    }
  }
  return files;
}

/// A run's frames to render (of `frames`, all the run has): one (--frame, or the last), or
/// every frame (in --frames' range), the last first so that its framing holds for all.
std::vector<std::filesystem::path> frames_to_render(const RenderCommandSettings& s,
                                                    std::vector<std::filesystem::path> frames) {
  if (!s.every_frame) return {s.frame > 0 ? run_frame_path(s.run, s.frame) : frames.back()};
  if (s.last_frame > 0) {
    std::erase_if(frames, [&](const std::filesystem::path& f) {
      return frame_number(f) < s.first_frame || frame_number(f) > s.last_frame;
    });
    if (frames.empty())
      throw std::invalid_argument("render: --frames " + std::to_string(s.first_frame) + " " +
                                  std::to_string(s.last_frame) + ": the run has none of those frames");
  }
  std::reverse(frames.begin(), frames.end());
  return frames;
}

/// Where mesh i of n goes side by side: centred in cell i of a grid about √(1.5 n) cells
/// wide (a row of ten grains framed was a thin line across the image), on the ground (z = 0).
Eigen::Affine3d grid_place(const grains::Vertices& V, int i, int n, const Eigen::Vector2d& cell) {
  const int columns = static_cast<int>(std::ceil(std::sqrt(1.5 * n)));
  const Eigen::Vector3d lo = V.colwise().minCoeff(), hi = V.colwise().maxCoeff();
  const Eigen::Vector2d centre(cell.x() * (i % columns), -cell.y() * (i / columns));
  Eigen::Affine3d place = Eigen::Affine3d::Identity();
  place.translation() =
      Eigen::Vector3d(centre.x() - 0.5 * (lo.x() + hi.x()), centre.y() - 0.5 * (lo.y() + hi.y()), -lo.z());
  return place;
}

/// The meshes given, each its own prototype: in place, or side by side on a grid.
void add_mesh_files(shading::RenderScene& scene, const RenderCommandSettings& s,
                    const std::vector<std::filesystem::path>& files, std::vector<Eigen::AlignedBox3d>& boxes) {
  Progress progress("render: meshes and curvature", static_cast<int>(files.size()));
  std::vector<grains::SurfaceMesh> meshes;
  Eigen::Vector2d cell = Eigen::Vector2d::Zero();  // side by side: 1.15 × the largest extents
  for (const auto& file : files) {
    stop_point();
    const grains::SurfaceMesh& mesh = meshes.emplace_back(grains::read_surface_mesh(file));
    cell = cell.cwiseMax(1.15 * (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).head<2>().transpose());
  }
  const int n = static_cast<int>(meshes.size());
  for (int i = 0; i < n; ++i) {
    const grains::SurfaceMesh& mesh = meshes[i];
    const Eigen::Affine3d place = s.side_by_side ? grid_place(mesh.V, i, n, cell) : Eigen::Affine3d::Identity();
    scene.add_instance(add_grain_prototype(scene, mesh.V, mesh.F, s.shading_radius), place, 0, i);
    Eigen::AlignedBox3d& box = boxes.emplace_back();
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) box.extend(place * mesh.V.row(v).transpose());
    progress.update(i + 1);
  }
  progress.finish();
}

/// What every image of one command shares, made once.
struct RenderInputs {
  std::vector<std::filesystem::path> files, frames;
  std::vector<std::filesystem::path> run_frames;  ///< every frame the run has
  std::shared_ptr<const RunVariants> variants;
  std::vector<ColliderDrawing> colliders;
  double fps = 30.0;  ///< the run's
  std::vector<shading::Material> materials;
  shading::CdrfTable cdrf{513, 513};
};

struct RenderTotals {
  shading::RenderStats stats;
  int instances = 0, prototypes = 0;
  int own_meshes = 0;  ///< soft grains drawn as their own deformed mesh (the last image's)
};

/// The times [s] of the run's frames.
std::vector<double> frame_times(const RenderInputs& in) {
  std::vector<double> times;
  for (const auto& frame : in.run_frames) times.push_back(frame_number(frame) / in.fps);
  return times;
}

/// The image of `scene` by the settings' integrator; its rays into `stats` (the path
/// tracer's paths as camera rays, its other rays as shadow rays).
shading::Image integrate(const RenderCommandSettings& s, const RenderInputs& in, const shading::RenderScene& scene,
                         const Stage& stage, shading::RenderStats& stats) {
  const shading::Camera& camera = stage.camera;
  const shading::Lights& lights = stage.lights;
  Progress progress("render: tiles", shading::tile_count(s.render));
  const auto update = [&](int done, int) { progress.update(done); };
  shading::Image image;
  if (s.integrator != RenderIntegrator::kPath && s.bounces == 0) {
    image = shading::render(scene, in.materials, lights, camera, in.cdrf, s.render, &stats, update, stop_requested);
  } else {
    const shading::RenderSettings& r = s.render;
    const bool reference = s.integrator == RenderIntegrator::kPath;
    shading::PathTraceSettings settings{.width = r.width, .height = r.height, .samples_per_pixel = r.samples_per_pixel,
                                        .sampler = r.sampler, .seed = r.seed,
                                        .max_depth = reference ? s.max_depth : 1 + s.bounces};
    settings.crop = r.crop;
    settings.adaptive = r.adaptive;
    if (!reference) settings.cdrf = &in.cdrf;  // the grains' fast model, not their medium
    std::vector<std::optional<shading::Medium>> media;
    if (reference) media.push_back(grain_medium(s.absorption_percent));
    shading::PathTraceStats path;
    image = shading::path_trace(scene, in.materials, media, lights, camera, settings, &path, update, stop_requested);
    stats = {path.paths, path.rays - path.paths, path.seconds};
  }
  progress.finish();
  stop_point();
  return image;
}

/// Image k's subject: the mesh files in `scene`, or the run's frame read into `grains` (drawn
/// once the camera is known), and the bowl in `scene`; returns the box that frames them.
Eigen::AlignedBox3d add_subject(shading::RenderScene& scene, const RenderCommandSettings& s, const RenderInputs& in,
                                const std::filesystem::path& frame, RunFrame& grains) {
  if (!s.run.empty()) {
    grains = read_run_frame(s.run, *in.variants, frame);
    return add_bowl(scene, s, framing_box(grains.boxes));
  }
  std::vector<Eigen::AlignedBox3d> boxes;
  add_mesh_files(scene, s, in.files, boxes);
  return add_bowl(scene, s, framing_box(boxes));
}

/// A video's stage: it frames the run's last frame and what any frame's colliders show.
Stage video_stage(const RenderCommandSettings& s, const RenderInputs& in, const Eigen::AlignedBox3d& last_frame) {
  return stage_for(s, last_frame.merged(drawn_colliders_box(in.colliders, frame_times(in))));
}

/// Image k: its scene, the stage (set on this image when none is yet), the render, its PNG
/// and its EXR with the AOVs.
void render_image(const RenderCommandSettings& s, const RenderInputs& in, int k, std::optional<Stage>& stage,
                  const std::filesystem::path& folder, RenderTotals& totals) {
  shading::RenderScene scene;
  RunFrame grains;
  const Eigen::AlignedBox3d box = add_subject(scene, s, in, s.run.empty() ? "" : in.frames[k], grains);
  if (!stage) stage = s.every_frame ? video_stage(s, in, box) : stage_for(s, box);  // image 0: the last frame
  if (!s.run.empty())
    totals.own_meshes =
        add_run_frame(scene, grains, *in.variants, s.soft, pixel_footprint(stage->camera, s.render.height));
  add_set(scene, s, *stage);
  if (!s.run.empty()) add_colliders(scene, in.colliders, frame_number(in.frames[k]) / in.fps, stage->camera.position);
  scene.commit();
  shading::RenderStats stats;
  const shading::Image image = integrate(s, in, scene, *stage, stats);
  const shading::Aovs aovs = shading::render_aovs(scene, in.materials, stage->camera, s.render.width, s.render.height,
                                                  s.render.crop);
  const std::string name = s.every_frame ? in.frames[k].stem().string() : "render";
  write_png(folder / (name + ".png"), tone_map(image, s.exposure));
  write_exr(folder / (name + ".exr"), exr_channels(image, &aovs, s.render.width, s.render.height, s.render.crop));
  totals.stats.camera_rays += stats.camera_rays;
  totals.stats.shadow_rays += stats.shadow_rays;
  totals.stats.seconds += stats.seconds;
  totals.instances = scene.instance_count();
  totals.prototypes = scene.prototype_count();
}

std::string vector_cell(const Eigen::Vector3d& v) { return cell(v.x()) + " " + cell(v.y()) + " " + cell(v.z()); }

std::string crop_cell(const shading::PixelWindow& crop) {
  if (crop.empty()) return "none";
  return cell(crop.x0) + " " + cell(crop.y0) + " " + cell(crop.x1) + " " + cell(crop.y1);
}

void write_render_info(const RenderCommandSettings& s, const RenderInputs& in, const shading::Camera& camera,
                       int images, const RenderTotals& totals, double wall_seconds,
                       const std::filesystem::path& folder) {
  const double rays = static_cast<double>(totals.stats.camera_rays + totals.stats.shadow_rays);
  const shading::PixelWindow window =
      shading::rendered_pixels(s.render.width, s.render.height, s.render.crop, "render");
  const double mean_samples = static_cast<double>(totals.stats.camera_rays) /
                              (static_cast<double>(window.width()) * window.height() * images);
  const std::string meshes = s.run.empty()    ? cell(static_cast<long>(in.files.size()))
                             : s.every_frame ? "run " + s.run.string() + ", every frame"
                                             : "run " + in.frames.front().string();
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "render"},
                                  {"meshes", meshes},
                                  {"images", cell(images)},
                                  {"frames", s.every_frame ? cell(frame_number(in.frames.back())) + " " +
                                                                 cell(frame_number(in.frames.front()))
                                                           : "n/a"},
                                  {"run_fps", s.run.empty() ? "n/a" : cell(in.fps)},
                                  {"instances", cell(totals.instances)},
                                  {"prototypes", cell(totals.prototypes)},
                                  {"soft_instance_pixels", cell(s.soft.instance_pixels)},
                                  {"soft_grains_own_mesh", cell(totals.own_meshes)},
                                  {"integrator", integrator_name(s.integrator)},
                                  {"max_depth", s.integrator == RenderIntegrator::kPath ? cell(s.max_depth) : "n/a"},
                                  {"bounces", s.integrator == RenderIntegrator::kPath ? "n/a" : cell(s.bounces)},
                                  {"absorption_percent", cell(s.absorption_percent)},
                                  {"sigma0_m", cell(in.materials[0].sigma0)},
                                  {"shading_radius_m", cell(s.shading_radius)},
                                  {"width", cell(s.render.width)},
                                  {"height", cell(s.render.height)},
                                  {"crop", crop_cell(s.render.crop)},
                                  {"camera_position_m", vector_cell(camera.position)},
                                  {"camera_target_m", vector_cell(camera.target)},
                                  {"camera_up", vector_cell(camera.up)},
                                  {"camera_fov_degrees", cell(camera.vertical_fov_degrees)},
                                  {"camera_aperture_m", cell(camera.aperture_radius)},
                                  {"camera_focus_m", cell(camera.focus_distance)},
                                  {"samples_per_pixel", cell(s.render.samples_per_pixel)},
                                  {"adaptive_error", cell(s.render.adaptive.relative_error)},
                                  {"adaptive_min_samples",
                                   s.render.adaptive.on() ? cell(s.render.adaptive.min_samples) : "n/a"},
                                  {"mean_samples_per_pixel", cell(mean_samples)},
                                  {"sampler", sampler_name(s.render.sampler)},
                                  {"seed", cell(static_cast<long>(s.render.seed))},
                                  {"lighting", s.lighting == Lighting::kStudio ? "studio" : "sun"},
                                  {"shadows", s.render.shadows ? "on" : "off"},
                                  {"ambient_occlusion", s.render.ambient_occlusion ? "on" : "off"},
                                  {"camera_rays", cell(static_cast<long>(totals.stats.camera_rays))},
                                  {"shadow_rays", cell(static_cast<long>(totals.stats.shadow_rays))},
                                  {"render_s", cell(totals.stats.seconds)},
                                  {"rays_per_second", cell(rays / totals.stats.seconds)},
                                  {"wall_s", cell(wall_seconds)}}));
  std::printf("render: %d image(s) of %d x %d at %.4g spp in %.1f s (%.2f M rays/s)\n", images, s.render.width,
              s.render.height, mean_samples, totals.stats.seconds, 1e-6 * rays / totals.stats.seconds);
}

}  // namespace

std::string integrator_name(RenderIntegrator integrator) {
  switch (integrator) {
    case RenderIntegrator::kCdrf: return "cdrf";
    case RenderIntegrator::kTranslucent: return "translucent";
    case RenderIntegrator::kPath: return "path";
  }
  return "?";
}

std::string sampler_name(shading::SamplerKind kind) {
  return kind == shading::SamplerKind::kSobol ? "sobol" : kind == shading::SamplerKind::kStratified ? "stratified" : "independent";
}

void validate(const RenderCommandSettings& s) {
  const auto files = mesh_files(s.meshes);
  if (files.empty() == s.run.empty())
    throw std::invalid_argument("render: give either --meshes (mesh files, or folders holding .ply or .obj files) or "
                                "--run (a scene run's output folder)");
  for (const auto& f : files)
    if (!std::filesystem::is_regular_file(f)) throw std::invalid_argument("render: " + f.string() + ": no such file");
  if (s.variants && s.variants->shading_radius != s.shading_radius)
    throw std::invalid_argument("render: the variants given were smoothed over another shading radius");
  if (!s.run.empty()) {
    for (const char* name : {"grains.csv", "variants", "frames"})
      if (!std::filesystem::exists(s.run / name))
        throw std::invalid_argument("render: --run " + s.run.string() + " has no " + name +
                                    " (a scene run's output folder is expected)");
    if (s.frame > 0 && !std::filesystem::exists(run_frame_path(s.run, s.frame)))
      throw std::invalid_argument("render: --frame " + std::to_string(s.frame) + ": no " +
                                  run_frame_path(s.run, s.frame).string());
  }
  if (s.frame < 0) throw std::invalid_argument("render: --frame must be >= 0");
  if (s.every_frame && (s.run.empty() || s.frame > 0))
    throw std::invalid_argument("render: --every-frame renders each frame of a --run, without --frame");
  if (s.video && !s.every_frame) throw std::invalid_argument("render: --video needs --every-frame");
  if ((s.first_frame != 0 || s.last_frame != 0) && !(s.every_frame && 0 < s.first_frame && s.first_frame <= s.last_frame))
    throw std::invalid_argument("render: --frames FIRST LAST needs --every-frame and 1 <= FIRST <= LAST");
  if (!(s.absorption_percent >= 0.0 && s.absorption_percent <= 100.0))
    throw std::invalid_argument("render: --absorption must be in [0, 100] %");
  if (s.render.width < 1 || s.render.height < 1 || s.render.width > 16384 || s.render.height > 16384)
    throw std::invalid_argument("render: --width and --height must be in [1, 16384]");
  const shading::PixelWindow& crop = s.render.crop;
  if (crop.x0 != 0 || crop.y0 != 0 || crop.x1 != 0 || crop.y1 != 0) {
    if (crop.empty()) throw std::invalid_argument("render: --crop x0 y0 x1 y1 needs x0 < x1 and y0 < y1");
    shading::rendered_pixels(s.render.width, s.render.height, crop, "render: --crop");
  }
  if (s.render.samples_per_pixel < 1 || s.render.samples_per_pixel > 1 << 20)
    throw std::invalid_argument("render: --spp must be in [1, 1048576]");
  if (s.max_depth < 1 || s.max_depth > 100000) throw std::invalid_argument("render: --max-depth must be in [1, 100000]");
  for (const auto& quad : s.area_lights)
    if (!(quad.edge_u.cross(quad.edge_v).norm() > 0.0f) || !(quad.radiance >= 0.0f).all())
      throw std::invalid_argument("render: an --area-light needs two edges that span an area and a radiance >= 0");
  if (!s.sky_image.empty() && !std::filesystem::is_regular_file(s.sky_image))
    throw std::invalid_argument("render: --sky-image " + s.sky_image.string() + ": no such file");
}

RenderOutcome render_command(const RenderCommandSettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  RenderInputs inputs;
  inputs.files = mesh_files(settings.meshes);
  if (!settings.run.empty()) {
    inputs.run_frames = run_frames(settings.run);
    inputs.frames = frames_to_render(settings, inputs.run_frames);
    inputs.variants = settings.variants ? settings.variants : std::make_shared<const RunVariants>(
                                                                  read_run_variants(settings.run, settings.shading_radius));
    inputs.colliders = read_collider_drawings(settings.run);
    inputs.fps = run_fps(settings.run);
  }
  inputs.materials = materials_of(settings.absorption_percent, settings.integrator);
  make_output_folder(folder);

  std::optional<Stage> stage;
  RenderTotals totals;
  if (settings.every_frame && inputs.frames.front() != inputs.run_frames.back()) {  // a part of the video
    shading::RenderScene bowl;
    RunFrame last_frame;
    stage = video_stage(settings, inputs, add_subject(bowl, settings, inputs, inputs.run_frames.back(), last_frame));
  }
  const int images = settings.run.empty() ? 1 : static_cast<int>(inputs.frames.size());
  Progress progress("render: frames", images);
  for (int k = 0; k < images; ++k) {
    render_image(settings, inputs, k, stage, folder, totals);
    progress.update(k + 1);
  }
  progress.finish();
  if (settings.video) {
    const int first = frame_number(inputs.frames.back());  // the frames ran last to first
    encode_video(folder, "frame_%04d.png", first, inputs.fps, "render.mp4");
    write_contact_sheet(folder, "frame_%04d.png", first, images, 12, std::min(settings.render.width, 320),
                        "contact_sheet.png");
  }
  const double wall_seconds = seconds_since(start);
  write_render_info(settings, inputs, stage->camera, images, totals, wall_seconds, folder);
  return {stage->camera, totals.stats, wall_seconds, totals.own_meshes};
}

void validate(const RunFrameImage& image) {
  if (image.run.empty() || !std::filesystem::is_directory(image.run))
    throw std::invalid_argument("--run: '" + image.run.string() + "' is not a run's folder");
  if (image.width < 1 || image.height < 1 || image.samples_per_pixel < 1)
    throw std::invalid_argument("--width, --height and --spp must be positive");
  if (image.eye.size() != image.look_at.size() || (image.eye.size() != 0 && image.eye.size() != 3))
    throw std::invalid_argument("--eye and --look-at: give both, x y z each, or neither");
}

RenderOutcome render_run_frame(const RunFrameImage& image, const SoftGrainDrawing& soft,
                               const std::filesystem::path& folder) {
  RenderCommandSettings r;
  r.run = image.run;
  r.frame = image.frame;
  r.render.width = image.width;
  r.render.height = image.height;
  r.render.samples_per_pixel = image.samples_per_pixel;
  if (!image.eye.empty()) {
    r.camera = shading::Camera{};
    r.camera->position = {image.eye[0], image.eye[1], image.eye[2]};
    r.camera->target = {image.look_at[0], image.look_at[1], image.look_at[2]};
  }
  r.soft = soft;
  return render_command(r, folder);
}

}  // namespace rice::experiments
