// A scene run's folder as the renderer reads it (written by the scene runner's observers):
// its variants' render meshes with their vertex curvature, its frames' poses, and each frame's
// grains. A rigid grain is an instance of its variant at c + q (drop + P R p − c₀)
// (grains.csv). A soft grain's frame rows are its simulation vertices, deformed; its render
// mesh rides on them through its variant's embedding (paper §4.3), each vertex at Σ_k w_k x_k,
// unless the grain is within SoftGrainDrawing::instance_pixels of a pixel's footprint of rigid:
// then it is an instance of its variant at its best rigid fit (rigid_fit.hpp), as a rigid
// grain is. A frame is read (read_run_frame: what frames the camera) before it is drawn
// (add_run_frame: the footprint comes from that camera).
#pragma once

#include <Eigen/Geometry>

#include <filesystem>
#include <vector>

#include "experiments/render/scene_pieces.hpp"
#include "grains/embedding.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "grains/mesh_types.hpp"
#include "shading/camera.hpp"
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
  /// A grain whose simulation vertices all lie within this many pixel footprints (at its
  /// distance from the camera) of its best rigid fit is an instance of its variant there; 0:
  /// every grain its own deformed mesh. An own mesh costs some 4.7 MB (its hierarchy): a
  /// fixed 20 µm, blind to the image, drew 889 of the rice cooker tenth's grains as their own
  /// at 640 × 480, where a pixel spans 0.45 mm (4.3 GB); a quarter of a footprint draws 15
  /// (289 MiB) and changes the image by 0.5% RMS (`rice study soft-instances`, docs/rendering.md).
  double instance_pixels = 0.25;
};

/// The width [m] a pixel of an image spans at a point: `per_metre` times its distance from `eye`.
struct PixelFootprint {
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  double per_metre = 0.0;
  double at(const Eigen::Vector3d& p) const { return per_metre * (p - eye).norm(); }
};

/// A pixel's footprint for `camera`'s images `height` pixels high: 2 tan(fov/2) / height a metre.
PixelFootprint pixel_footprint(const shading::Camera& camera, int height);

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

/// A rigid grain of a frame: its variant placed.
struct PlacedGrain {
  int grain = 0, variant = 0;
  Eigen::Affine3d place = Eigen::Affine3d::Identity();
};

/// The grains in the scene at a run's frame (those still parked left out), read and not yet
/// drawn: a rigid run's placed, a soft run's vertices; and each one's box.
struct RunFrame {
  std::vector<PlacedGrain> rigid;
  std::vector<SoftGrain> soft;
  std::vector<Eigen::AlignedBox3d> boxes;  ///< of every 16th vertex of each one's render mesh
};

/// Reads `frame` of `run`; throws std::runtime_error naming the file for a frame that does
/// not match grains.csv or the variants.
RunFrame read_run_frame(const std::filesystem::path& run, const RunVariants& variants,
                        const std::filesystem::path& frame);

/// Adds the frame's grains to `scene` with material 0 and their index in grains.csv as label:
/// a rigid grain as an instance of its variant, a soft one as `soft` says, its tolerance
/// `soft.instance_pixels` × `footprint` at its centre. Returns how many soft grains were
/// drawn as their own mesh.
int add_run_frame(shading::RenderScene& scene, const RunFrame& frame, const RunVariants& variants,
                  const SoftGrainDrawing& soft, const PixelFootprint& footprint);

}  // namespace rice::experiments
