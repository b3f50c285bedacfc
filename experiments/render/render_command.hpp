// `rice render`: renders grain meshes (the PLY/OBJ files of `rice grains`, or any closed
// meshes) or a frame of a rigid `rice pour` (its grains instanced from its variants, and its
// chawan, glazed) as cooked rice with the CDRF (paper §4.4), on an optional ground, under a
// sun and a uniform or image sky, from a camera given on the command line or framed
// automatically.
// Writes render.png (tone mapped), render.exr (linear) — frame_NNNN.png and .exr for every
// frame of a pour — and run_info.txt (settings, ray counts, rays per second, wall time).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shading/camera.hpp"
#include "shading/lights.hpp"
#include "shading/material.hpp"
#include "shading/render_scene.hpp"
#include "shading/random_walk.hpp"
#include "shading/renderer.hpp"

namespace rice::experiments {

struct RenderCommandSettings {
  std::vector<std::filesystem::path> meshes;  ///< files, or folders whose .ply/.obj files are read
  std::filesystem::path pour;                 ///< or: the output folder of a rigid `rice pour`
  int frame = 0;                              ///< of the pour; 0: its last
  double absorption_percent = 20.0;           ///< water absorption W: σ0 and albedo of the CDRF
  shading::RenderSettings render;
  std::optional<shading::Camera> camera;  ///< none: framed on the meshes' bounds
  double sun_elevation_degrees = 50.0, sun_azimuth_degrees = -30.0;
  double sun_irradiance = 3.0;  ///< [W/m²-like units]; 0: no sun
  double sun_diameter_degrees = 0.53;
  std::vector<shading::QuadLight> area_lights;
  double sky_radiance = 0.3;    ///< uniform sky; ignored with sky_image
  std::filesystem::path sky_image;  ///< latitude–longitude OpenEXR, z up
  bool ground = true;           ///< a grey plane under the meshes
  bool side_by_side = false;    ///< each mesh centred on its own spot along x (`rice grains` output)
  double exposure = 0.0;        ///< stops, PNG only
  /// A pour's every frame, into frame_NNNN.png and .exr, with one camera: the given one or the
  /// last frame's framing. The variants' curvature and the CDRF table are made once.
  bool every_frame = false;
};

/// Throws std::invalid_argument naming the setting that is out of range or the file missing.
void validate(const RenderCommandSettings& settings);

/// Renders into `folder`; returns the camera it used (the framed one when none was given).
shading::Camera render_command(const RenderCommandSettings& settings, const std::filesystem::path& folder);

/// The rice material at water absorption W: CDRF σ0 and albedo from the water-content model,
/// and a wet, slightly rough dielectric surface.
shading::Material rice_material(double absorption_percent);

/// The grain's medium at water absorption W for the random-walk reference: the optics of the
/// water-content model, isotropic scattering with μs = μs' (the similarity relation).
shading::Medium grain_medium(double absorption_percent);

/// Adds `V, F` as a prototype with its jet-fitted vertex curvature; returns its index.
int add_grain_prototype(shading::RenderScene& scene, const shading::MeshVertices& V, const shading::MeshTriangles& F);

/// Adds the rectangle [x0, x1] × [y0, y1] at height z, facing +z (a ground, a plate, a
/// cloth), as its own prototype and instance with `material`.
void add_ground(shading::RenderScene& scene, double x0, double y0, double x1, double y1, double z, int material);

/// A camera that frames `bounds` from the given elevation and azimuth [degrees].
shading::Camera framing_camera(const Eigen::AlignedBox3f& bounds, double elevation_degrees, double azimuth_degrees,
                               double vertical_fov_degrees, double aspect);

}  // namespace rice::experiments
