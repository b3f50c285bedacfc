// A scene run's frames, read for rendering; see run_frames.hpp.
#include "experiments/render/run_frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <stdexcept>

#include "experiments/io/numeric_csv.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/rigid_fit.hpp"
#include "grains/embedding.hpp"
#include "grains/mesh_io.hpp"
#include "shading/curvature.hpp"
#include "shading/smooth_normals.hpp"

namespace rice::experiments {

std::filesystem::path run_frame_path(const std::filesystem::path& run, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.csv", frame);
  return run / "frames" / name;
}

double run_fps(const std::filesystem::path& run) {
  const std::string fps = run_info_value(run / "run_info.txt", "fps");
  return fps.empty() ? 30.0 : std::stod(fps);
}

int frame_number(const std::filesystem::path& frame) {
  const std::string stem = frame.stem().string();
  return std::stoi(stem.substr(stem.find('_') + 1));
}

std::vector<std::filesystem::path> run_frames(const std::filesystem::path& run) {
  std::vector<std::filesystem::path> frames;
  for (const auto& entry : std::filesystem::directory_iterator(run / "frames"))
    if (entry.path().extension() == ".csv") frames.push_back(entry.path());
  if (frames.empty()) throw std::runtime_error("render: " + (run / "frames").string() + " holds no frame");
  std::sort(frames.begin(), frames.end());
  return frames;
}

namespace {

/// Which of `variants` (its meshes read) the run's grains.csv names (all of them without one):
/// a run of 3 grains drawn from 8 variants shades 3 (0.8 s a variant at the default radius).
std::vector<bool> variants_used(const std::filesystem::path& run, const RunVariants& variants) {
  if (!std::filesystem::exists(run / "grains.csv")) return std::vector<bool>(variants.meshes.size(), true);
  const NumericCsv grains_csv = read_numeric_csv(run / "grains.csv");
  std::vector<bool> used(variants.meshes.size(), false);
  for (size_t g = 0; g < grains_csv.rows.size(); ++g) used[grain_variant(grains_csv, g, variants)] = true;
  return used;
}

}  // namespace

RunVariants read_run_variants(const std::filesystem::path& run, double shading_radius) {
  RunVariants variants;
  variants.shading_radius = shading_radius;
  for (int k = 0;; ++k) {
    auto path = run / "variants" / ("variant_" + std::to_string(k) + ".ply");
    if (!std::filesystem::exists(path)) break;
    variants.meshes.push_back(grains::read_surface_mesh(path));
    if (std::filesystem::exists(path.replace_extension(".mesh"))) variants.simulation.push_back(grains::read_medit(path));
  }
  if (!variants.simulation.empty() && variants.simulation.size() != variants.meshes.size())
    throw std::runtime_error("render: " + (run / "variants").string() + " holds simulation meshes for " +
                             std::to_string(variants.simulation.size()) + " of its " +
                             std::to_string(variants.meshes.size()) + " variants");
  const std::vector<bool> used = variants_used(run, variants);
  variants.shading.resize(variants.meshes.size());
  variants.embedding.resize(variants.simulation.size());
  Progress progress("render: variants, curvature and embeddings", static_cast<int>(variants.meshes.size()));
  for (size_t k = 0; k < variants.meshes.size(); ++k) {
    if (used[k]) {
      variants.shading[k] = grain_shading(variants.meshes[k].V, variants.meshes[k].F, shading_radius);
      if (!variants.simulation.empty())
        variants.embedding[k] = grains::embed_points(variants.meshes[k].V, variants.simulation[k]);
    }
    progress.update(static_cast<int>(k + 1));
  }
  progress.finish();
  return variants;
}

namespace {

double value(const NumericCsv& csv, const std::vector<double>& row, const std::string& name) {
  return row[csv.column(name)];
}

/// The columns PREFIXx, PREFIXy, PREFIXz of a row.
Eigen::Vector3d xyz(const NumericCsv& csv, const std::vector<double>& row, const std::string& prefix) {
  return {value(csv, row, prefix + "x"), value(csv, row, prefix + "y"), value(csv, row, prefix + "z")};
}

/// The columns qw, qx, qy, qz of a row.
Eigen::Quaterniond quaternion(const NumericCsv& csv, const std::vector<double>& row) {
  return {value(csv, row, "qw"), value(csv, row, "qx"), value(csv, row, "qy"), value(csv, row, "qz")};
}

/// False for a row of a grain still parked far away.
bool in_scene(const NumericCsv& frame, const std::vector<double>& row) {
  const bool marked = std::find(frame.columns.begin(), frame.columns.end(), "in_scene") != frame.columns.end();
  return !marked || value(frame, row, "in_scene") != 0.0;
}

/// The box of every 16th vertex of V placed.
Eigen::AlignedBox3d placed_box(const grains::Vertices& V, const Eigen::Affine3d& place) {
  Eigen::AlignedBox3d box;
  for (Eigen::Index v = 0; v < V.rows(); v += 16) box.extend(place * V.row(v).transpose());
  return box;
}

/// The box of every 16th vertex of a soft grain's render mesh, carried by its simulation
/// vertices (the coarse tets are inscribed: their vertices' box missed the mesh by 10%).
Eigen::AlignedBox3d embedded_box(const SoftGrain& grain, const RunVariants& variants) {
  const grains::Embedding& embedding = variants.embedding[grain.variant];
  Eigen::AlignedBox3d box;
  for (Eigen::Index v = 0; v < embedding.tet.size(); v += 16)
    box.extend(grains::embedded_point(embedding, v, grain.x, variants.simulation[grain.variant].T));
  return box;
}

/// Each variant's prototype, added the first time a grain needs it.
class VariantPrototypes {
 public:
  VariantPrototypes(shading::RenderScene& scene, const RunVariants& variants)
      : scene_(scene), variants_(variants), index_(variants.meshes.size(), -1) {}
  int operator[](int variant) {
    if (index_[variant] < 0) {
      index_[variant] = add_grain_prototype(scene_, variants_.meshes[variant].V, variants_.meshes[variant].F,
                                            variants_.shading[variant]);
    }
    return index_[variant];
  }

 private:
  shading::RenderScene& scene_;
  const RunVariants& variants_;
  std::vector<int> index_;
};

/// One row per grain: its variant placed by rigid_grain_place, and its box.
void read_rigid_grains(const NumericCsv& grains_csv, const NumericCsv& frame, const RunVariants& variants,
                       RunFrame& out) {
  check_rigid_frame(grains_csv, frame);
  for (size_t g = 0; g < grains_csv.rows.size(); ++g) {
    const int variant = grain_variant(grains_csv, g, variants);
    if (!in_scene(frame, frame.rows[g])) continue;
    out.rigid.push_back({.grain = static_cast<int>(g), .variant = variant,
                         .place = rigid_grain_place(grains_csv, frame, g)});
    out.boxes.push_back(placed_box(variants.meshes[variant].V, out.rigid.back().place));
  }
}

/// Grain g's simulation vertices: the frame's rows from `row` on, which it moves past them.
grains::Vertices simulation_vertices(const NumericCsv& frame, size_t g, Eigen::Index count, size_t& row) {
  if (row + count > frame.rows.size())
    throw std::runtime_error("render: " + frame.path.string() + " ends before grain " + std::to_string(g) +
                             "'s " + std::to_string(count) + " simulation vertices");
  const int grain = frame.column("grain"), vertex = frame.column("vertex");
  const int x = frame.column("x"), y = frame.column("y"), z = frame.column("z");
  grains::Vertices V(count, 3);
  for (Eigen::Index v = 0; v < count; ++v, ++row) {
    const auto& r = frame.rows[row];
    if (r[grain] != static_cast<double>(g) || r[vertex] != static_cast<double>(v))
      throw std::runtime_error("render: " + frame.path.string() + ": row " + std::to_string(row + 1) +
                               " is not grain " + std::to_string(g) + "'s vertex " + std::to_string(v) +
                               " (its variant's simulation mesh has " + std::to_string(count) + ")");
    V.row(v) << r[x], r[y], r[z];
  }
  return V;
}

/// A soft grain as its own render mesh, carried by its simulation vertices.
void add_own_mesh(shading::RenderScene& scene, const SoftGrain& grain, const RunVariants& variants,
                  SoftCurvature curvature) {
  const grains::SurfaceMesh mesh = deformed_render_mesh(grain, variants);
  const GrainShading& rest = variants.shading[grain.variant];
  // The rest normals carried by the tets' deformation (smoothing the deformed mesh anew cost
  // 90 ms a grain); the rest curvature and thickness scaled by the swell (a grain at rest
  // deforms by a few per cent), or its own curvature.
  const grains::VolumeMesh& simulation = variants.simulation[grain.variant];
  GrainShading drawn{.curvature = rest.curvature / grain.swell,
                     .thickness = rest.thickness * grain.swell,
                     .normals = grains::carry_normals(variants.embedding[grain.variant], rest.normals, simulation.V,
                                                      grain.x, simulation.T)};
  if (curvature == SoftCurvature::kDeformed)
    drawn.curvature = shading::smoothed_vertex_values(mesh.V, mesh.F, shading::vertex_mean_curvature(mesh.V, mesh.F),
                                                      curvature_radius(variants.shading_radius));
  scene.add_instance(add_grain_prototype(scene, mesh.V, mesh.F, drawn, shading::RenderScene::Reuse::kSingle),
                     Eigen::Affine3d::Identity(), 0, grain.grain);
}

/// Where grain's variant stands in for it: its best rigid fit, when all its vertices lie
/// within `tolerance` [m] of it.
std::optional<Eigen::Affine3d> instance_place(const SoftGrain& grain, const RunVariants& variants, double tolerance) {
  if (!(tolerance > 0.0)) return std::nullopt;
  const RigidFit fit = fit_rigid_motion(variants.simulation[grain.variant].V, grain.swell, grain.x);
  if (fit.residual > tolerance) return std::nullopt;
  return fit.place;
}

}  // namespace

int grain_variant(const NumericCsv& grains_csv, size_t g, const RunVariants& variants) {
  const int variant = static_cast<int>(value(grains_csv, grains_csv.rows[g], "variant"));
  if (variant < 0 || variant >= static_cast<int>(variants.meshes.size()))
    throw std::runtime_error("render: " + grains_csv.path.string() + ": grain " + std::to_string(g) +
                             " names variant " + std::to_string(variant) + " of " +
                             std::to_string(variants.meshes.size()));
  return variant;
}

void check_rigid_frame(const NumericCsv& grains_csv, const NumericCsv& frame) {
  if (frame.rows.size() != grains_csv.rows.size())
    throw std::runtime_error("render: " + frame.path.string() + " has " + std::to_string(frame.rows.size()) +
                             " grains, grains.csv " + std::to_string(grains_csv.rows.size()));
}

Eigen::Affine3d rigid_grain_place(const NumericCsv& grains_csv, const NumericCsv& frame, size_t g) {
  const auto& a = grains_csv.rows[g];
  const auto& b = frame.rows[g];
  const Eigen::Quaterniond R = quaternion(grains_csv, a), q = quaternion(frame, b);
  const Eigen::Vector3d drop = xyz(grains_csv, a, "drop_"), c0 = xyz(grains_csv, a, "centre_"), c = xyz(frame, b, "");
  return Eigen::Translation3d(c) * q.normalized() * Eigen::Translation3d(drop - c0) * R.normalized() *
         Eigen::Scaling(value(grains_csv, a, "swell"));
}

std::vector<SoftGrain> soft_run_grains(const NumericCsv& grains_csv, const NumericCsv& frame,
                                       const RunVariants& variants, bool parked_too) {
  if (variants.simulation.empty())
    throw std::runtime_error("render: " + frame.path.string() +
                             " holds soft grains' vertices, and the run's variants/ no simulation meshes (.mesh)");
  std::vector<SoftGrain> grains;
  size_t row = 0;
  for (size_t g = 0; g < grains_csv.rows.size(); ++g) {
    const int variant = grain_variant(grains_csv, g, variants);
    const grains::VolumeMesh& simulation = variants.simulation[variant];
    const grains::Vertices x = simulation_vertices(frame, g, simulation.V.rows(), row);
    if (!parked_too && !in_scene(frame, frame.rows[row - 1])) continue;
    grains.push_back({.grain = static_cast<int>(g),
                      .variant = variant,
                      .swell = value(grains_csv, grains_csv.rows[g], "swell"),
                      .x = x});
  }
  if (row != frame.rows.size())
    throw std::runtime_error("render: " + frame.path.string() + " has " + std::to_string(frame.rows.size() - row) +
                             " rows past the last grain's vertices");
  return grains;
}

grains::SurfaceMesh deformed_render_mesh(const SoftGrain& grain, const RunVariants& variants) {
  return {grains::apply_embedding(variants.embedding[grain.variant], grain.x, variants.simulation[grain.variant].T),
          variants.meshes[grain.variant].F};
}

PixelFootprint pixel_footprint(const shading::Camera& camera, int height) {
  const double half_fov = 0.5 * camera.vertical_fov_degrees * std::numbers::pi / 180.0;
  return {camera.position, 2.0 * std::tan(half_fov) / height};
}

RunFrame read_run_frame(const std::filesystem::path& run, const RunVariants& variants,
                        const std::filesystem::path& frame) {
  const NumericCsv grains_csv = read_numeric_csv(run / "grains.csv");
  const NumericCsv poses = read_numeric_csv(frame);
  RunFrame out;
  if (std::find(poses.columns.begin(), poses.columns.end(), "vertex") == poses.columns.end()) {
    read_rigid_grains(grains_csv, poses, variants, out);
    return out;
  }
  out.soft = soft_run_grains(grains_csv, poses, variants);
  for (const SoftGrain& grain : out.soft) out.boxes.push_back(embedded_box(grain, variants));
  return out;
}

int add_run_frame(shading::RenderScene& scene, const RunFrame& frame, const RunVariants& variants,
                  const SoftGrainDrawing& soft, const PixelFootprint& footprint) {
  VariantPrototypes prototype(scene, variants);
  for (const PlacedGrain& grain : frame.rigid)
    scene.add_instance(prototype[grain.variant], grain.place, 0, grain.grain);
  int own = 0;
  for (const SoftGrain& grain : frame.soft) {
    const double tolerance = soft.instance_pixels * footprint.at(grain.x.colwise().mean().transpose());
    if (const auto place = instance_place(grain, variants, tolerance)) {
      scene.add_instance(prototype[grain.variant], *place, 0, grain.grain);
    } else {
      add_own_mesh(scene, grain, variants, soft.curvature);
      ++own;
    }
  }
  return own;
}

}  // namespace rice::experiments
