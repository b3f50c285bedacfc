// What surrounds the grains in a render, and what sees and lights them: the materials by
// index, the camera (given, or framed on the grains), the lights (the studio's, or the sun and
// sky), the set under the grains (the studio's table and backdrop, or a grey ground), a run's
// chawan and its colliders as they are at the frame's time.
#pragma once

#include <Eigen/Geometry>

#include <vector>

#include "experiments/render/render_command.hpp"
#include "experiments/render/collider_drawing.hpp"
#include "shading/render_scene.hpp"

namespace rice::experiments {

/// The materials by index: 0 the grains' rice (the translucent model's, or the paper's CDRF),
/// 1 the grey ground, 2 the dark glazed chawan, 3 the studio's table (a light linen), 4 its
/// backdrop (a warm grey), then the colliders' (collider_drawing.hpp): 5 white plastic, 6 pale
/// wood, 7 steel (a rough metal), 8 glazed white ceramic.
std::vector<shading::Material> materials_of(double absorption_percent, RenderIntegrator integrator);

/// What every image of one command is seen and lit by, set by the first image rendered (a
/// run's last frame): the camera, the subject it frames and the lights.
struct Stage {
  shading::Camera camera;
  Eigen::AlignedBox3d subject;
  shading::Lights lights;
};

/// The stage for grains (and bowl) in `subject`: the given camera or one framing it from 35°
/// up, and the settings' lights.
Stage stage_for(const RenderCommandSettings& s, const Eigen::AlignedBox3d& subject);

/// Under the subject: the studio's table and backdrop, or a grey ground a square four times
/// the subject's extent, just under its lowest point; nothing without `ground`.
void add_set(shading::RenderScene& scene, const RenderCommandSettings& s, const Stage& stage);

/// A run's chawan, glazed. Returns the box of the grains and the bowl.
Eigen::AlignedBox3d add_bowl(shading::RenderScene& scene, const RenderCommandSettings& s,
                             const Eigen::AlignedBox3d& grains_box);

/// The run's colliders present at `time` [s], posed; a mould cut away towards `eye`. Not
/// framed: a lid high above or a wall would shrink the grains.
void add_colliders(shading::RenderScene& scene, const std::vector<ColliderDrawing>& colliders, double time,
                   const Eigen::Vector3d& eye);

}  // namespace rice::experiments
