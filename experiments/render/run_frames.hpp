// A scene run's folder as the renderer reads it (written by the scene runner's observers):
// its variants' render meshes with their vertex curvature, its frames' poses, and each frame's
// grains. A rigid grain is an instance of its variant at c + q (drop + P R p − c₀)
// (grains.csv). A soft grain's frame rows are its simulation vertices, deformed; its render
// mesh rides on them through its variant's embedding (paper §4.3), each vertex at Σ_k w_k x_k,
// unless the grain is within SoftGrainDrawing::instance_tolerance of rigid: then it is an
// instance of its variant at its best rigid fit (rigid_fit.hpp), as a rigid grain is.
#pragma once

#include <Eigen/Geometry>

#include <filesystem>
#include <vector>

#include "experiments/render/scene_pieces.hpp"
#include "grains/embedding.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "grains/mesh_types.hpp"
#include "shading/render_scene.hpp"

namespace rice::experiments {

/// frames/frame_NNNN.csv of the run.
std::filesystem::path run_frame_path(const std::filesystem::path& run, int frame);

/// N of a frame's file (frame_NNNN.csv, .png, ...).
int frame_number(const std::filesystem::path& frame);

/// The run's frames, in order; throws std::runtime_error when it has none.
std::vector<std::filesystem::path> run_frames(const std::filesystem::path& run);

/// The run's frame rate, from the `fps:` line of its run_info.txt; 30 when it has none.
double run_fps(const std::filesystem::path& run);

/// The curvature H a soft grain's render mesh is shaded with.
enum class SoftCurvature {
  kRest,      ///< its variant's rest curvature, scaled by 1/P: free
  kDeformed,  ///< recomputed on the deformed mesh of every grain in every frame
};

/// How a soft run's grains are drawn (docs/rendering.md measures both knobs).
struct SoftGrainDrawing {
  SoftCurvature curvature = SoftCurvature::kRest;  ///< of the grains drawn as their own mesh
  /// [m] A grain whose simulation vertices all lie this close to its best rigid fit is an
  /// instance of its variant there; 0: every grain its own deformed mesh. The default is
  /// under a pixel of a 4K frame of a 10 cm scene (26 µm); on the onigiri's last frame it
  /// instances 304 of 793 grains and changes the image by 0.47% RMS (`rice study
  /// soft-instances`, docs/rendering.md).
  double instance_tolerance = 2e-5;
};

/// The run's variants and their shading (curvature, normals, thickness), computed once for
/// every frame rendered; for a soft run also their simulation meshes and the render meshes'
/// embeddings in them. A variant no grain uses has empty shading and embedding.
struct RunVariants {
  std::vector<grains::SurfaceMesh> meshes;
  std::vector<GrainShading> shading;
  double shading_radius = kShadingRadius;      ///< [m] what `shading` was smoothed over
  std::vector<grains::VolumeMesh> simulation;  ///< empty for a rigid run
  std::vector<grains::Embedding> embedding;
};

/// The variants of a run's folder, shaded at `shading_radius` [m] (0: the meshes' own normals
/// and curvature).
RunVariants read_run_variants(const std::filesystem::path& run, double shading_radius = kShadingRadius);

/// A soft grain at a frame.
struct SoftGrain {
  int grain = 0, variant = 0;
  double swell = 1.0;  ///< P (grains.csv)
  grains::Vertices x;  ///< its simulation vertices
};

/// The soft grains in the scene at `frame` (a soft run's, whose rows are grain, vertex,
/// x, y, z and in_scene), in grain order; with `parked_too` every grain. Throws
/// std::runtime_error naming the file when the rows do not match the grains' variants.
std::vector<SoftGrain> soft_run_grains(const NumericCsv& grains_csv, const NumericCsv& frame,
                                       const RunVariants& variants, bool parked_too = false);

/// Grain g's variant (grains.csv); throws std::runtime_error when `variants` has no such one.
int grain_variant(const NumericCsv& grains_csv, size_t g, const RunVariants& variants);

/// Throws std::runtime_error when a rigid run's frame has not one row per grain of grains.csv.
void check_rigid_frame(const NumericCsv& grains_csv, const NumericCsv& frame);

/// Where a rigid run's frame puts grain g's variant mesh: c + q (drop + P R p − c₀) (grains.csv's
/// drop, R, P and c₀; the frame's centre c and rotation q).
Eigen::Affine3d rigid_grain_place(const NumericCsv& grains_csv, const NumericCsv& frame, size_t g);

/// Its render mesh, carried by its simulation vertices through its variant's embedding.
grains::SurfaceMesh deformed_render_mesh(const SoftGrain& grain, const RunVariants& variants);

/// Adds the grains in the scene at `frame` (those still parked are left out), with material 0
/// and their index in grains.csv as label,
/// and appends each one's box to `boxes`: a rigid run's as instances of the variants, a soft
/// run's as `soft` says. Returns how many soft grains were drawn as their own mesh. Throws
/// std::runtime_error naming the file for a frame that does not match grains.csv or the
/// variants.
int add_run_grains(shading::RenderScene& scene, const std::filesystem::path& run, const RunVariants& variants,
                   const std::filesystem::path& frame, std::vector<Eigen::AlignedBox3d>& boxes,
                   const SoftGrainDrawing& soft = {});

}  // namespace rice::experiments
