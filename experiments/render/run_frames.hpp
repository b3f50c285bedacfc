// A scene run's folder as the renderer reads it (written by the scene runner's observers):
// its variants' render meshes with their vertex curvature, its frames' poses, and each frame's
// grains as instances of the variants at c + q (drop + P R p − c₀) (grains.csv). Rigid grains
// only: a soft run's frames hold simulation vertices.
#pragma once

#include <Eigen/Geometry>

#include <filesystem>
#include <vector>

#include "grains/mesh_types.hpp"
#include "shading/render_scene.hpp"

namespace rice::experiments {

/// frames/frame_NNNN.csv of the run.
std::filesystem::path run_frame_path(const std::filesystem::path& run, int frame);

/// The run's frames, in order; throws std::runtime_error when it has none.
std::vector<std::filesystem::path> run_frames(const std::filesystem::path& run);

/// The run's variants and their vertex curvature, computed once for every frame rendered.
struct RunVariants {
  std::vector<grains::SurfaceMesh> meshes;
  std::vector<Eigen::VectorXd> curvature;
};

RunVariants read_run_variants(const std::filesystem::path& run);

/// Adds the grains in the scene at `frame` (those still parked are left out) as instances of
/// the variants, with material 0, and grows `box` by them. Throws std::runtime_error naming the
/// file for a soft run's frame or one that does not match grains.csv.
void add_run_grains(shading::RenderScene& scene, const std::filesystem::path& run, const RunVariants& variants,
                    const std::filesystem::path& frame, Eigen::AlignedBox3d& box);

}  // namespace rice::experiments
