// How a run's colliders are drawn. Each collider a scene adds beside its container — a mould,
// a lid, the press's hand, a wall — is a surface mesh in its own frame with a material name
// from the scene file (`[[colliders]] material`), and its keyframes and removal time. The run
// writes them into colliders/ (collider_K.obj in the collider's frame, colliders.csv with one
// row per keyframe) and `rice render --run` draws each while it is present at the frame's
// time, posed as the solver posed it (xpbd::collider_pose).
// A hollow mesh (a mould: the room inside it) is drawn cut away, as a technical drawing shows
// a mould: only its walls behind what it holds, seen from inside (cutaway_walls); drawn whole,
// the room's surface hid every grain in it.
// Analytic shapes are tessellated: a plane as a square 20 cm across (the solid's top face), a
// sphere and a capsule as lathes of 48 × 24 quads, a box as its six faces.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "grains/mesh_types.hpp"
#include "xpbd/collider.hpp"

namespace rice::experiments {

/// The materials a collider can be drawn in, by name: plastic, wood, steel, ceramic. Inline:
/// the scene reader names them without linking what draws them.
inline const std::vector<std::string>& collider_material_names() {
  static const std::vector<std::string> names = {"plastic", "wood", "steel", "ceramic"};
  return names;
}

struct ColliderDrawing {
  grains::SurfaceMesh mesh;  ///< in the collider's frame [m], outward
  std::string material;      ///< plastic, wood, steel or ceramic
  xpbd::Collider motion;     ///< its keyframes and removal time (shape and sizes unused)
  bool hollow = false;       ///< a mould: `mesh` bounds the room inside it
  /// A collider that yields (yield.csv): how far it stood back from its keyframes at each frame's
  /// time, as (time [s], world offset [m]); empty for one that follows them.
  std::vector<std::pair<double, Eigen::Vector3d>> yielded = {};
};

/// A hollow collider's walls as seen from `eye` (in the collider's frame): the triangles whose
/// outward normal faces away from the eye, turned to face into the room.
grains::SurfaceMesh cutaway_walls(const grains::SurfaceMesh& room, const Eigen::Vector3d& eye);

/// Where the collider's frame is at `time` [s]: translation · rotation · scale, as the solver
/// posed it (xpbd::collider_pose), moved by its yield offset (linear between frames).
Eigen::Affine3d collider_placement(const ColliderDrawing& collider, double time);

/// The union of the colliders' boxes, each as posed at every one of `times` [s] when it is
/// present. What a video's camera frames beside the grains: framed on its last frame's grains
/// alone, the bunny's video cut off the mould's top. Empty for none.
Eigen::AlignedBox3d drawn_colliders_box(const std::vector<ColliderDrawing>& colliders,
                                        const std::vector<double>& times);

/// An analytic collider's surface in its own frame; throws std::invalid_argument for a
/// distance-grid collider (a mesh collider draws its own mesh).
grains::SurfaceMesh collider_surface(const xpbd::Collider& collider);

/// colliders/collider_K.obj (K from 1) and colliders/colliders.csv; nothing for no colliders.
void write_collider_drawings(const std::vector<ColliderDrawing>& drawings, const std::filesystem::path& run);

/// What write_collider_drawings wrote (none when the run has no colliders/), with the offsets
/// of yield.csv when the run has it. Throws
/// std::runtime_error naming the file for a table that does not match its meshes.
std::vector<ColliderDrawing> read_collider_drawings(const std::filesystem::path& run);

}  // namespace rice::experiments
