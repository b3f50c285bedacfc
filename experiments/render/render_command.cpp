// `rice render`; see render_command.hpp.
#include "experiments/render/render_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "experiments/io/interrupt.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/io/render_images.hpp"
#include "grains/mesh_io.hpp"
#include "grains/water_content.hpp"
#include "shading/curvature.hpp"

namespace rice::experiments {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

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

std::filesystem::path pour_frame_path(const std::filesystem::path& pour, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.csv", frame);
  return pour / "frames" / name;
}

// The pour's variants (its render meshes) and their vertex curvature, computed once for every
// frame rendered.
struct PourVariants {
  std::vector<grains::SurfaceMesh> meshes;
  std::vector<Eigen::VectorXd> curvature;
};

PourVariants read_pour_variants(const std::filesystem::path& pour) {
  PourVariants variants;
  for (int k = 0;; ++k) {
    const auto path = pour / "variants" / ("variant_" + std::to_string(k) + ".ply");
    if (!std::filesystem::exists(path)) break;
    variants.meshes.push_back(grains::read_surface_mesh(path));
  }
  Progress progress("render: variants and curvature", static_cast<int>(variants.meshes.size()));
  for (size_t k = 0; k < variants.meshes.size(); ++k) {
    variants.curvature.push_back(shading::vertex_mean_curvature(variants.meshes[k].V, variants.meshes[k].F));
    progress.update(static_cast<int>(k + 1));
  }
  progress.finish();
  return variants;
}

// The pour's frames, in order.
std::vector<std::filesystem::path> pour_frames(const std::filesystem::path& pour) {
  std::vector<std::filesystem::path> frames;
  for (const auto& entry : std::filesystem::directory_iterator(pour / "frames"))
    if (entry.path().extension() == ".csv") frames.push_back(entry.path());
  if (frames.empty()) throw std::runtime_error("render: " + (pour / "frames").string() + " holds no frame");
  std::sort(frames.begin(), frames.end());
  return frames;
}

// Instances of the pour's variants at a frame's poses: c + q (drop + P R p − c₀).
void add_pour_grains(shading::RenderScene& scene, const std::filesystem::path& pour, const PourVariants& variants,
                     const std::filesystem::path& frame, Eigen::AlignedBox3d& box) {
  const NumericCsv grains_csv = read_numeric_csv(pour / "grains.csv");
  const NumericCsv poses = read_numeric_csv(frame);
  if (poses.columns.size() < 2 || poses.columns[1] != "x")
    throw std::runtime_error("render: " + frame.string() + " holds soft-body vertices; only rigid pours are rendered");
  if (poses.rows.size() != grains_csv.rows.size())
    throw std::runtime_error("render: " + frame.string() + " has " + std::to_string(poses.rows.size()) +
                             " grains, grains.csv " + std::to_string(grains_csv.rows.size()));
  std::vector<int> prototype;
  for (size_t k = 0; k < variants.meshes.size(); ++k)
    prototype.push_back(scene.add_prototype(variants.meshes[k].V, variants.meshes[k].F, variants.curvature[k]));
  const auto col = [&](const NumericCsv& csv, const std::vector<double>& row, const char* name) {
    return row[csv.column(name)];
  };
  const bool marked = std::find(poses.columns.begin(), poses.columns.end(), "in_scene") != poses.columns.end();
  for (size_t g = 0; g < grains_csv.rows.size(); ++g) {
    const auto& a = grains_csv.rows[g];
    const auto& b = poses.rows[g];
    if (marked && col(poses, b, "in_scene") == 0.0) continue;  // still parked far away
    const int variant = static_cast<int>(col(grains_csv, a, "variant"));
    if (variant < 0 || variant >= static_cast<int>(prototype.size()))
      throw std::runtime_error("render: " + (pour / "grains.csv").string() + ": grain " + std::to_string(g) +
                               " names variant " + std::to_string(variant) + " of " + std::to_string(prototype.size()));
    const Eigen::Quaterniond R(col(grains_csv, a, "qw"), col(grains_csv, a, "qx"), col(grains_csv, a, "qy"),
                               col(grains_csv, a, "qz"));
    const Eigen::Quaterniond q(col(poses, b, "qw"), col(poses, b, "qx"), col(poses, b, "qy"), col(poses, b, "qz"));
    const Eigen::Vector3d drop(col(grains_csv, a, "drop_x"), col(grains_csv, a, "drop_y"), col(grains_csv, a, "drop_z"));
    const Eigen::Vector3d c0(col(grains_csv, a, "centre_x"), col(grains_csv, a, "centre_y"), col(grains_csv, a, "centre_z"));
    const Eigen::Vector3d c(col(poses, b, "x"), col(poses, b, "y"), col(poses, b, "z"));
    const Eigen::Affine3d place = Eigen::Translation3d(c) * q.normalized() * Eigen::Translation3d(drop - c0) *
                                  R.normalized() * Eigen::Scaling(col(grains_csv, a, "swell"));
    scene.add_instance(prototype[variant], place, 0);
    const auto& V = variants.meshes[variant].V;
    for (Eigen::Index v = 0; v < V.rows(); v += 16) box.extend(place * V.row(v).transpose());
  }
}

Eigen::Vector3d direction_from(double elevation_degrees, double azimuth_degrees) {
  const double e = elevation_degrees * kDegree, a = azimuth_degrees * kDegree;
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

}  // namespace

shading::Material rice_material(double absorption_percent) {
  return {.kind = shading::MaterialKind::kRice,
          .albedo = shading::Color::Constant(static_cast<float>(grains::WaterContentModel::cdrf_albedo(absorption_percent))),
          .sigma0 = grains::WaterContentModel::scattering_sigma0(absorption_percent),
          .refractive_index = grains::WaterContentModel::optics(absorption_percent).refractive_index,
          .roughness = 0.25};
}

shading::Medium grain_medium(double absorption_percent) {
  const grains::GrainOptics optics = grains::WaterContentModel::optics(absorption_percent);
  return {optics.reduced_scattering, optics.absorption, 0.0, optics.refractive_index};
}

int add_grain_prototype(shading::RenderScene& scene, const shading::MeshVertices& V, const shading::MeshTriangles& F) {
  return scene.add_prototype(V, F, shading::vertex_mean_curvature(V, F));
}

void add_ground(shading::RenderScene& scene, double x0, double y0, double x1, double y1, double z, int material) {
  shading::MeshVertices V(4, 3);
  V << x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z;
  shading::MeshTriangles F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  scene.add_instance(scene.add_prototype(V, F), Eigen::Affine3d::Identity(), material);
}

shading::Camera framing_camera(const Eigen::AlignedBox3f& bounds, double elevation_degrees, double azimuth_degrees,
                               double vertical_fov_degrees, double aspect) {
  const Eigen::Vector3d centre = bounds.center().cast<double>();
  const double radius = 0.5 * bounds.diagonal().norm();
  const double half = 0.5 * vertical_fov_degrees * kDegree;
  const double fit = std::min(std::tan(half), std::tan(half) * aspect);  // the narrower side
  shading::Camera camera;
  camera.target = centre;
  camera.position = centre + direction_from(elevation_degrees, azimuth_degrees) * (1.05 * radius / std::sin(std::atan(fit)));
  camera.vertical_fov_degrees = vertical_fov_degrees;
  return camera;
}

void validate(const RenderCommandSettings& s) {
  const auto files = mesh_files(s.meshes);
  if (files.empty() == s.pour.empty())
    throw std::invalid_argument("render: give either --meshes (mesh files, or folders holding .ply or .obj files) or "
                                "--pour (a rice pour's output folder)");
  for (const auto& f : files)
    if (!std::filesystem::is_regular_file(f)) throw std::invalid_argument("render: " + f.string() + ": no such file");
  if (!s.pour.empty()) {
    for (const char* name : {"grains.csv", "variants", "frames"})
      if (!std::filesystem::exists(s.pour / name))
        throw std::invalid_argument("render: --pour " + s.pour.string() + " has no " + name +
                                    " (a rigid pour's output folder is expected)");
    if (s.frame > 0 && !std::filesystem::exists(pour_frame_path(s.pour, s.frame)))
      throw std::invalid_argument("render: --frame " + std::to_string(s.frame) + ": no " +
                                  pour_frame_path(s.pour, s.frame).string());
  }
  if (s.frame < 0) throw std::invalid_argument("render: --frame must be >= 0");
  if (s.every_frame && (s.pour.empty() || s.frame > 0))
    throw std::invalid_argument("render: --every-frame renders each frame of a --pour, without --frame");
  if (!(s.absorption_percent >= 0.0 && s.absorption_percent <= 100.0))
    throw std::invalid_argument("render: --absorption must be in [0, 100] %");
  if (s.render.width < 1 || s.render.height < 1 || s.render.width > 16384 || s.render.height > 16384)
    throw std::invalid_argument("render: --width and --height must be in [1, 16384]");
  if (s.render.samples_per_pixel < 1 || s.render.samples_per_pixel > 1 << 20)
    throw std::invalid_argument("render: --spp must be in [1, 1048576]");
  for (const auto& quad : s.area_lights)
    if (!(quad.edge_u.cross(quad.edge_v).norm() > 0.0f) || !(quad.radiance >= 0.0f).all())
      throw std::invalid_argument("render: an --area-light needs two edges that span an area and a radiance >= 0");
  if (!s.sky_image.empty() && !std::filesystem::is_regular_file(s.sky_image))
    throw std::invalid_argument("render: --sky-image " + s.sky_image.string() + ": no such file");
}

shading::Camera render_command(const RenderCommandSettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  const auto files = mesh_files(settings.meshes);
  // A pour's frames to render: one, or every frame, the last first so that its framing holds
  // for all. The variants' curvature and the CDRF table are made once for all of them.
  std::vector<std::filesystem::path> frames;
  if (!settings.pour.empty()) {
    frames = pour_frames(settings.pour);
    if (settings.every_frame) {
      std::reverse(frames.begin(), frames.end());
    } else {
      frames = {settings.frame > 0 ? pour_frame_path(settings.pour, settings.frame) : frames.back()};
    }
  }
  const PourVariants variants = settings.pour.empty() ? PourVariants{} : read_pour_variants(settings.pour);
  const std::vector<shading::Material> materials = {
      rice_material(settings.absorption_percent),
      {.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color::Constant(0.35f)},
      {.kind = shading::MaterialKind::kGlazed, .albedo = shading::Color(0.12f, 0.1f, 0.09f), .roughness = 0.08}};
  shading::Lights lights;
  if (settings.sun_irradiance > 0.0) {
    lights.suns.push_back({.direction = direction_from(settings.sun_elevation_degrees, settings.sun_azimuth_degrees).cast<float>(),
                           .angular_radius = static_cast<float>(0.5 * settings.sun_diameter_degrees * kDegree),
                           .irradiance = shading::Color::Constant(static_cast<float>(settings.sun_irradiance))});
  }
  lights.quads = settings.area_lights;
  if (!settings.sky_image.empty()) {
    shading::Image sky = read_exr(settings.sky_image);
    lights.environment.width = sky.width;
    lights.environment.height = sky.height;
    lights.environment.image = std::move(sky.pixels);
  } else {
    lights.environment.constant = shading::Color::Constant(static_cast<float>(settings.sky_radiance));
  }
  const shading::CdrfTable cdrf(513, 513);
  make_output_folder(folder);

  std::optional<shading::Camera> camera = settings.camera;
  shading::RenderStats stats;
  int instances = 0, prototypes = 0;
  const int images = settings.pour.empty() ? 1 : static_cast<int>(frames.size());
  Progress frame_progress("render: frames", images);
  for (int k = 0; k < images; ++k) {
    shading::RenderScene scene;
    Eigen::AlignedBox3d box;
    if (!settings.pour.empty()) {
      add_pour_grains(scene, settings.pour, variants, frames[k], box);
    } else {
      Progress progress("render: meshes and curvature", static_cast<int>(files.size()));
      double next_x = 0.0;  // side by side: the next mesh's left edge
      for (size_t i = 0; i < files.size(); ++i) {
        stop_point();
        grains::SurfaceMesh mesh = grains::read_surface_mesh(files[i]);
        Eigen::Affine3d place = Eigen::Affine3d::Identity();
        if (settings.side_by_side) {
          const Eigen::Vector3d lo = mesh.V.colwise().minCoeff(), hi = mesh.V.colwise().maxCoeff();
          place.translation() = Eigen::Vector3d(next_x - lo.x(), -0.5 * (lo.y() + hi.y()), -lo.z());
          next_x += 1.15 * (hi.x() - lo.x());
        }
        scene.add_instance(add_grain_prototype(scene, mesh.V, mesh.F), place, 0);
        for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) box.extend(place * mesh.V.row(v).transpose());
        progress.update(static_cast<int>(i + 1));
      }
      progress.finish();
    }
    Eigen::AlignedBox3d scene_box = box;  // grains, and the bowl when there is one
    if (!settings.pour.empty() && std::filesystem::exists(settings.pour / "chawan.obj")) {
      const grains::SurfaceMesh bowl = grains::read_surface_mesh(settings.pour / "chawan.obj");
      scene.add_instance(scene.add_prototype(bowl.V, bowl.F), Eigen::Affine3d::Identity(), 2);  // a dark glazed chawan
      for (Eigen::Index v = 0; v < bowl.V.rows(); ++v) scene_box.extend(bowl.V.row(v).transpose());
    }
    if (settings.ground) {
      // A square four times the meshes' extent, just under their lowest point.
      const double half = 2.0 * scene_box.diagonal().head<2>().maxCoeff() + 1e-3, z = scene_box.min().z() - 1e-6;
      const Eigen::Vector2d c = scene_box.center().head<2>();
      add_ground(scene, c.x() - half, c.y() - half, c.x() + half, c.y() + half, z, 1);
    }
    scene.commit();
    if (!camera) {
      const double aspect = static_cast<double>(settings.render.width) / settings.render.height;
      const Eigen::AlignedBox3f grains_box(scene_box.min().cast<float>(), scene_box.max().cast<float>());
      camera = framing_camera(grains_box, 35.0, -60.0, 30.0, aspect);
    }
    shading::RenderStats frame_stats;
    Progress progress("render: tiles", shading::tile_count(settings.render));
    const shading::Image image = shading::render(scene, materials, lights, *camera, cdrf, settings.render, &frame_stats,
                                                 [&](int done, int) { progress.update(done); }, stop_requested);
    progress.finish();
    stop_point();
    const std::string name = settings.every_frame ? frames[k].stem().string() : "render";
    write_png(folder / (name + ".png"), tone_map(image, settings.exposure));
    write_exr(folder / (name + ".exr"), image);
    stats.camera_rays += frame_stats.camera_rays;
    stats.shadow_rays += frame_stats.shadow_rays;
    stats.seconds += frame_stats.seconds;
    instances = scene.instance_count();
    prototypes = scene.prototype_count();
    frame_progress.update(k + 1);
  }
  frame_progress.finish();
  const double rays = static_cast<double>(stats.camera_rays + stats.shadow_rays);
  const std::string meshes = settings.pour.empty() ? cell(static_cast<long>(files.size()))
                             : settings.every_frame ? "pour " + settings.pour.string() + ", every frame"
                                                    : "pour " + frames.front().string();
  write_file_atomically(
      folder / "run_info.txt",
      run_info({{"command", "render"},
                {"meshes", meshes},
                {"images", cell(images)},
                {"instances", cell(instances)},
                {"prototypes", cell(prototypes)},
                {"absorption_percent", cell(settings.absorption_percent)},
                {"sigma0_m", cell(materials[0].sigma0)},
                {"width", cell(settings.render.width)},
                {"height", cell(settings.render.height)},
                {"samples_per_pixel", cell(settings.render.samples_per_pixel)},
                {"sampler", settings.render.sampler == shading::SamplerKind::kSobol        ? "sobol"
                            : settings.render.sampler == shading::SamplerKind::kStratified ? "stratified"
                                                                                           : "independent"},
                {"seed", cell(static_cast<long>(settings.render.seed))},
                {"shadows", settings.render.shadows ? "on" : "off"},
                {"ambient_occlusion", settings.render.ambient_occlusion ? "on" : "off"},
                {"camera_rays", cell(static_cast<long>(stats.camera_rays))},
                {"shadow_rays", cell(static_cast<long>(stats.shadow_rays))},
                {"render_s", cell(stats.seconds)},
                {"rays_per_second", cell(rays / stats.seconds)},
                {"wall_s", cell(seconds_since(start))}}));
  std::printf("render: %d image(s) of %d x %d at %d spp in %.1f s (%.2f M rays/s)\n", images, settings.render.width,
              settings.render.height, settings.render.samples_per_pixel, stats.seconds, 1e-6 * rays / stats.seconds);
  return *camera;
}

}  // namespace rice::experiments
