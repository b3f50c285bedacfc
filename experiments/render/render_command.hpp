// `rice render`: renders grain meshes (the PLY/OBJ files of `rice grains`, or any closed
// meshes) or a frame of a scene run (`rice run`: its rigid grains instanced from its variants,
// its soft grains' render meshes carried by their simulation meshes, run_frames.hpp, and its
// chawan, glazed) as cooked rice with the CDRF (paper §4.4), the translucent model (the CDRF
// and the light through the grain), either with bounces of light between surfaces, or with
// the reference path tracer (shading/path_tracer.hpp: light through and between the grains, their medium at the
// water absorption W), lit by a food photographer's studio (studio_lighting.hpp) or by a sun
// and a uniform or image sky over a ground, from a camera given on the command line or framed
// automatically.
// Writes render.png (tone mapped), render.exr (linear, with the AOV layers of
// shading/aovs.hpp) — frame_NNNN.png and .exr for every frame of a run, and render.mp4 and
// contact_sheet.png of them with `video` — and run_info.txt (settings, the camera, ray
// counts, rays per second, wall time). With a crop window, the images are that part of the
// frame; its EXR's data window places it in the frame for merge_crops (crop_merge.hpp).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "experiments/render/run_frames.hpp"
#include "experiments/render/studio_lighting.hpp"
#include "shading/camera.hpp"
#include "shading/lights.hpp"
#include "shading/material.hpp"
#include "shading/renderer.hpp"

namespace rice::experiments {

enum class RenderIntegrator {
  kCdrf,         ///< the paper's CDRF (shading/renderer.hpp; with bounces, the path tracer's fast model)
  kTranslucent,  ///< the CDRF with the light through the grain, τ(d, cos θ) (shading/translucency.hpp)
  kPath,         ///< the reference path tracer (shading/path_tracer.hpp)
};

enum class Lighting {
  kStudio,  ///< a food photographer's key, fill, table and backdrop (studio_lighting.hpp)
  kSun,     ///< the sun, area lights and a sky over a grey ground
};

struct RenderCommandSettings {
  std::vector<std::filesystem::path> meshes;  ///< files, or folders whose .ply/.obj files are read
  std::filesystem::path run;                  ///< or: the output folder of a scene run
  int frame = 0;                              ///< of the run; 0: its last
  double absorption_percent = 20.0;           ///< water absorption W: σ0 and albedo of the CDRF
  shading::RenderSettings render;
  RenderIntegrator integrator = RenderIntegrator::kCdrf;
  int max_depth = 64;  ///< the path tracer's surface events per path
  int bounces = 0;     ///< cdrf, translucent: bounces of light between surfaces (0: direct light)
  std::optional<shading::Camera> camera;  ///< none: framed on the meshes' bounds
  Lighting lighting = Lighting::kStudio;
  StudioLighting studio;
  double sun_elevation_degrees = 50.0, sun_azimuth_degrees = -30.0;
  double sun_irradiance = 3.0;  ///< [W/m²-like units]; 0: no sun
  double sun_diameter_degrees = 0.53;
  std::vector<shading::QuadLight> area_lights;
  double sky_radiance = 0.3;    ///< uniform sky; ignored with sky_image
  std::filesystem::path sky_image;  ///< latitude–longitude OpenEXR, z up
  bool ground = true;           ///< the studio's table and backdrop, or the sun's grey ground
  bool side_by_side = false;    ///< each mesh centred in its own cell of a grid (`rice grains` output)
  double exposure = 0.0;        ///< stops, PNG only
  /// A run's every frame, into frame_NNNN.png and .exr, with one camera: the given one or the
  /// last frame's framing. The variants' curvature and the CDRF table are made once.
  bool every_frame = false;
  bool video = false;  ///< with every_frame: render.mp4 at the run's frame rate and contact_sheet.png (io/video.hpp)
  /// With every_frame: only frames first_frame .. last_frame (0 0: all), with the camera of the
  /// whole video, so that groups of frames rendered by separate processes join into one video
  /// (`rice join-video`).
  int first_frame = 0, last_frame = 0;
  SoftGrainDrawing soft;  ///< how a soft run's grains are drawn
  double shading_radius = kShadingRadius;  ///< [m] grains' normals and curvature smoothed over it (scene_pieces.hpp)
  /// The run's variants, read once by a caller that renders one run many times (a study); null:
  /// read here. Their curvature is smoothed over their own shading_radius, which must match.
  std::shared_ptr<const RunVariants> variants;
};

/// Throws std::invalid_argument naming the setting that is out of range or the file missing.
void validate(const RenderCommandSettings& settings);

/// "cdrf", "translucent", "path"; "independent", "stratified", "sobol".
std::string integrator_name(RenderIntegrator integrator);
std::string sampler_name(shading::SamplerKind kind);

struct RenderOutcome {
  shading::Camera camera;     ///< the camera it used (the framed one when none was given)
  shading::RenderStats stats;  ///< rays and seconds of the rendering itself, every image's
  double wall_seconds = 0.0;   ///< of the whole command, reading the run included
  int own_meshes = 0;          ///< soft grains drawn as their own deformed mesh (the last image's)
};

/// Renders into `folder`.
RenderOutcome render_command(const RenderCommandSettings& settings, const std::filesystem::path& folder);

/// One frame of a scene run at a preview size: what the soft-grain studies render.
struct RunFrameImage {
  std::filesystem::path run;  ///< a soft scene run's output folder
  int frame = 0;              ///< 0: its last
  int width = 320, height = 240, samples_per_pixel = 16;
  std::vector<double> eye, look_at;  ///< [m] x y z of the camera and its target; none: framed on the grains
};

/// Throws std::invalid_argument for a missing run folder, sizes that are not positive, or an
/// eye without a target (or the other way round).
void validate(const RunFrameImage& image);

/// The image rendered with the run's soft grains drawn as `soft`, into `folder`.
RenderOutcome render_run_frame(const RunFrameImage& image, const SoftGrainDrawing& soft,
                               const std::filesystem::path& folder);

}  // namespace rice::experiments
