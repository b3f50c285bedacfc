// Scene files (issue 13): a scene described in one TOML file (experiments/scenes/*.toml) and
// run by `rice run SCENE.toml --out DIR` (scene_run.hpp), without writing C++. Read strictly, before any work:
// a syntax error, a section or key that does not exist, a value of the wrong type or out of
// range stops the run with a SceneError whose message names the file, the line and the key
// and says what was expected.
//
// Sections and keys (all optional; the defaults are those of `rice pour`):
//
//   [scene]      name (text; default: the file's stem), description (text)
//   [grains]     cultivar, count, variants, seed, body ("rigid" | "soft"), young_pa, poisson,
//                soak_minutes, soak_temperature_c
//   [solver]     fps, frames, substeps (0: by body kind), iterations,
//                method ("xpbd" | "vbd"; vbd needs soft grains)
//   [container]  kind ("chawan" | "plate"), grid_spacing_m (the chawan's distance grid),
//                scale (the chawan's sizes times this; 1: 12 cm across)
//   [emitter]    kind ("spout" | "fill"). spout: height_m (above the chawan's rim or the
//                plate), radius_m (its opening; 0: the container's), seconds (over which the
//                grains leave it; 0: all at once, a clump). fill: mould, the number of a hollow
//                mesh in [[colliders]] (1 for the first), which the grains fill in rounds
//                round_s apart (default 0.5), each at the free points of a lattice of their
//                boxes, lowest first
//   [effects]    friction (bool), static_friction, dynamic_friction, cohesion, sleeping,
//                render_meshes
//   [render]     width, height, samples_per_pixel, sun_elevation_deg, sun_azimuth_deg,
//                sun_irradiance, sky_radiance, ground (bool), eye_m and look_at_m (both or
//                neither; neither: framed on the grains), fov_deg; rigid grains only
//   [[colliders]] (any number, beside the container) shape ("plane" | "sphere" | "box" |
//                "capsule" | "mesh") with its sizes (radius_m; half_extents_m = [x, y, z];
//                radius_m and half_length_m; a mesh: file, a closed .obj/.off/.ply from the
//                scene file's folder, scale, hollow (the room inside, a mould), grid_spacing_m
//                of its distance grid), static_friction and dynamic_friction (default: the
//                grains'), removed_at_s (gone from then on: a mould taken away), and its pose:
//                position_m = [x, y, z], axis = [x, y, z], angle_deg (a plane is the solid
//                below its local z = 0), or keyframes = [{ time_s, position_m, axis,
//                angle_deg }, ...] at increasing times, so a hand can press and withdraw
//
// Overrides (`--set section.key=value`, a TOML value) replace or add a key before reading, so
// a short variant of a scene is the same file with fewer grains or frames.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/scene/pour_scene.hpp"

namespace rice::experiments {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `[render]`: the last frame rendered after the simulation (rigid grains), by `rice render`'s
/// renderer with the CDRF at the grains' water content.
struct SceneRender {
  int width = 640, height = 480;
  int samples_per_pixel = 16;
  double sun_elevation_degrees = 50.0, sun_azimuth_degrees = -30.0;
  double sun_irradiance = 3.0;  ///< 0: no sun
  double sky_radiance = 0.3;
  bool ground = true;
  /// The camera, when the file gives one; otherwise it frames the grains.
  std::optional<xpbd::Vec3> eye, look_at;
  double vertical_fov_degrees = 30.0;
  /// Also every frame, into render_frames/frame_NNNN.png, with the last frame's camera.
  bool every_frame = false;
};

struct SceneDescription {
  std::string name;
  std::string description;
  /// What runs: for now every scene is grains poured from a spout into a container.
  PourSettings pour;
  std::optional<SceneRender> render;  ///< none: no [render] section
};

/// Reads scene text; `source` names it in messages (a file path). `overrides` are
/// "section.key=value" strings applied before reading.
SceneDescription parse_scene(std::string_view text, const std::string& source, const std::vector<std::string>& overrides = {});

/// The file's text (SceneError when it cannot be read).
std::string read_scene_text(const std::filesystem::path& path);

/// Reads a scene file (SceneError when it cannot be read).
SceneDescription read_scene_file(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});

}  // namespace rice::experiments
