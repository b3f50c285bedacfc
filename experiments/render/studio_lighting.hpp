// The default lighting of `rice render` and of every scene's render: a food photographer's
// set, built around what the camera frames. A large soft key light (a softbox, a quad light
// two subject sizes across) high to one side of the camera, a fill as large on the other side
// at a quarter of the key's irradiance, both a warm white; a table under the subject and a
// backdrop behind it, so that nothing in the frame is the void; and a dim room light from
// everywhere. The sun and uniform sky of the earlier renders stay as `lighting = "sun"`.
// Every size is in units of the subject's size, so a single grain and a rice cooker are lit
// alike.
#pragma once

#include <Eigen/Geometry>

#include "shading/lights.hpp"
#include "shading/render_scene.hpp"

namespace rice::experiments {

struct StudioLighting {
  double key_irradiance = 3.0;    ///< at the subject's centre, facing the key (the sun's default); the warm white's red
  double fill_ratio = 0.25;       ///< fill irradiance / key irradiance
  double key_elevation_degrees = 45.0;
  double key_azimuth_degrees = 60.0;  ///< from the camera's side, towards its left (positive) or right
  double room_radiance = 0.04;    ///< the uniform light of the room
};

/// The key, the fill and the room light for `subject` seen from `eye`. The subject box must
/// not be empty.
shading::Lights studio_lights(const Eigen::AlignedBox3d& subject, const Eigen::Vector3d& eye,
                              const StudioLighting& lighting);

/// The table (material `table`) under `subject` and the backdrop (material `backdrop`)
/// behind it, seen from `eye`.
void add_studio_set(shading::RenderScene& scene, const Eigen::AlignedBox3d& subject, const Eigen::Vector3d& eye,
                    int table, int backdrop);

}  // namespace rice::experiments
