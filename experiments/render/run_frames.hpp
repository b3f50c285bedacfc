// A scene run's folder as the renderer reads it (written by the scene runner's observers):
// its variants' render meshes with their vertex curvature, its frames' poses, and each frame's
// grains. A rigid grain is an instance of its variant at c + q (drop + P R p − c₀)
// (grains.csv). A soft grain's frame rows are its simulation vertices, deformed; its render
// mesh rides on them through its variant's embedding (paper §4.3), each vertex at Σ_k w_k x_k.
#pragma once

#include <Eigen/Geometry>

#include <filesystem>
#include <vector>

#include "grains/embedding.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "grains/mesh_types.hpp"
#include "shading/render_scene.hpp"

namespace rice::experiments {

/// frames/frame_NNNN.csv of the run.
std::filesystem::path run_frame_path(const std::filesystem::path& run, int frame);

/// The run's frames, in order; throws std::runtime_error when it has none.
std::vector<std::filesystem::path> run_frames(const std::filesystem::path& run);

/// The curvature H a soft grain's render mesh is shaded with.
enum class SoftCurvature {
  kRest,      ///< its variant's rest curvature, scaled by 1/P: free
  kDeformed,  ///< recomputed on the deformed mesh of every grain in every frame
};

/// The run's variants and their vertex curvature, computed once for every frame rendered; for
/// a soft run also their simulation meshes and the render meshes' embeddings in them.
struct RunVariants {
  std::vector<grains::SurfaceMesh> meshes;
  std::vector<Eigen::VectorXd> curvature;
  std::vector<grains::VolumeMesh> simulation;  ///< empty for a rigid run
  std::vector<grains::Embedding> embedding;
};

RunVariants read_run_variants(const std::filesystem::path& run);

/// A soft grain at a frame: its render mesh through its variant's embedding.
struct SoftGrain {
  int grain = 0, variant = 0;
  double swell = 1.0;  ///< P (grains.csv)
  grains::SurfaceMesh mesh;
};

/// The soft grains in the scene at `frame` (a soft run's, whose rows are grain, vertex,
/// x, y, z and in_scene), in grain order. Throws std::runtime_error naming the file when the
/// rows do not match the grains' variants.
std::vector<SoftGrain> soft_run_grains(const NumericCsv& grains_csv, const NumericCsv& frame,
                                       const RunVariants& variants);

/// Adds the grains in the scene at `frame` (those still parked are left out), with material 0,
/// and appends each one's box to `boxes`: a rigid run's as instances of the variants, a soft run's each as its
/// own deformed mesh. Throws std::runtime_error naming the file for a frame that does not
/// match grains.csv or the variants.
void add_run_grains(shading::RenderScene& scene, const std::filesystem::path& run, const RunVariants& variants,
                    const std::filesystem::path& frame, std::vector<Eigen::AlignedBox3d>& boxes,
                    SoftCurvature curvature = SoftCurvature::kRest);

}  // namespace rice::experiments
