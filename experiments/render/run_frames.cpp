// A scene run's frames, read for rendering; see run_frames.hpp.
#include "experiments/render/run_frames.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "experiments/io/numeric_csv.hpp"
#include "experiments/io/progress.hpp"
#include "grains/mesh_io.hpp"
#include "shading/curvature.hpp"

namespace rice::experiments {

std::filesystem::path run_frame_path(const std::filesystem::path& run, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.csv", frame);
  return run / "frames" / name;
}

std::vector<std::filesystem::path> run_frames(const std::filesystem::path& run) {
  std::vector<std::filesystem::path> frames;
  for (const auto& entry : std::filesystem::directory_iterator(run / "frames"))
    if (entry.path().extension() == ".csv") frames.push_back(entry.path());
  if (frames.empty()) throw std::runtime_error("render: " + (run / "frames").string() + " holds no frame");
  std::sort(frames.begin(), frames.end());
  return frames;
}

RunVariants read_run_variants(const std::filesystem::path& run) {
  RunVariants variants;
  for (int k = 0;; ++k) {
    const auto path = run / "variants" / ("variant_" + std::to_string(k) + ".ply");
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

void add_run_grains(shading::RenderScene& scene, const std::filesystem::path& run, const RunVariants& variants,
                    const std::filesystem::path& frame, Eigen::AlignedBox3d& box) {
  const NumericCsv grains_csv = read_numeric_csv(run / "grains.csv");
  const NumericCsv poses = read_numeric_csv(frame);
  if (poses.columns.size() < 2 || poses.columns[1] != "x")
    throw std::runtime_error("render: " + frame.string() + " holds soft-body vertices; only rigid runs are rendered");
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
      throw std::runtime_error("render: " + (run / "grains.csv").string() + ": grain " + std::to_string(g) +
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

}  // namespace rice::experiments
