// Static or kinematic colliders that grains touch: a half-space, a sphere, a box, a capsule
// (analytic signed distances) and any closed mesh as a sampled distance field
// (distance_grid.hpp), each in its own frame, placed in the world by a rigid motion
// prescribed over time (keyframes). A collider has infinite mass; friction against it uses the
// displacement of its surface over the substep. One with a force limit gives way, as a hand
// does: pushed back by the grains harder than that along its yield axis, it slides back along
// the axis from its keyframed pose (ColliderYield), and returns to it as the load falls.
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "xpbd/distance_grid.hpp"

#include "xpbd/rigid_body.hpp"

namespace rice::xpbd {

enum class ColliderShape {
  kHalfSpace,  ///< solid below the local plane z = 0 (normal +z)
  kSphere,     ///< radius about the local origin
  kBox,        ///< half_extents about the local origin
  kCapsule,    ///< radius about the local segment z ∈ [−half_length, half_length]
  kDistanceGrid,  ///< the sampled field `grid` (a bowl, a plate, a mould, a hand)
};

/// A pose of the collider's frame at a time: world = translation + rotation · (scale · local).
/// A scale that changes over the keyframes is a mould that closes on what it holds.
struct ColliderKeyframe {
  double time = 0.0;  ///< [s]
  Vec3 translation = Vec3::Zero();
  Quat rotation = Quat::Identity();
  double scale = 1.0;  ///< uniform, about the collider frame's origin
};

/// A yielding collider's offset from its keyframed pose along its yield axis, s(t) = offset +
/// rate (t − time) ≥ 0 over one substep from `time`, and the force the grains put on it along
/// the axis in the substep before. The contact solver sets it at each substep's start
/// (next_yield). Run state, kept in checkpoints.
struct ColliderYield {
  double time = 0.0;    ///< [s]
  double offset = 0.0;  ///< s [m]
  double rate = 0.0;    ///< ṡ [m/s]
  double force = 0.0;   ///< F [N], along the yield axis
};

struct Collider {
  ColliderShape shape = ColliderShape::kHalfSpace;
  Vec3 half_extents = Vec3::Zero();  ///< box [m]
  double radius = 0.0;               ///< sphere, capsule [m]
  double half_length = 0.0;          ///< capsule [m]
  std::shared_ptr<const DistanceGrid> grid;  ///< kDistanceGrid (shared: grids are large)
  /// Poses at increasing times, interpolated linearly (translation, scale) and by slerp (rotation),
  /// held constant before the first and after the last. One keyframe: a static collider.
  std::vector<ColliderKeyframe> motion{ColliderKeyframe{}};
  double static_friction = 0.0;   ///< μ_s against grains
  double dynamic_friction = 0.0;  ///< μ_k against grains
  /// [s] From this time on the collider is gone (a mould taken away); the sleeping bodies it
  /// touched wake.
  double removal_time = INFINITY;
  /// [N] The most the collider pushes with along −yield_axis; INFINITY: kinematic, it pushes
  /// with whatever force its keyframes take (a grain caught between it and the floor is
  /// crushed).
  double force_limit = INFINITY;
  Vec3 yield_axis = Vec3::UnitZ();  ///< world, unit: the way it gives (up, for a lid)
  /// [m/s] v_y: how fast it backs off at twice its force limit, and returns to its keyframes
  /// with no load (next_yield).
  double yield_speed = 0.01;
  ColliderYield yield;
};

/// Whether the collider gives way past a force (Collider::force_limit).
inline bool yields(const Collider& collider) { return std::isfinite(collider.force_limit); }

/// Whether the collider is there at time t (before its removal time).
inline bool collider_present(const Collider& collider, double time) { return time < collider.removal_time; }

/// Whether two poses are the same to the bit (a collider between them is at rest).
inline bool same_pose(const ColliderKeyframe& a, const ColliderKeyframe& b) {
  return a.translation == b.translation && a.rotation.coeffs() == b.rotation.coeffs() && a.scale == b.scale;
}

inline Vec3 to_world(const ColliderKeyframe& pose, const Vec3& local) {
  return pose.translation + pose.rotation * (pose.scale * local);
}
inline Vec3 to_local(const ColliderKeyframe& pose, const Vec3& world) {
  return pose.rotation.conjugate() * (world - pose.translation) / pose.scale;
}

/// The collider's pose at time t: its keyframes', moved by its yield offset s(t) along its
/// yield axis when it yields.
ColliderKeyframe collider_pose(const Collider& collider, double time);

/// The yield offset s(t) [m] (0 for a collider that does not yield).
double yield_offset(const Collider& collider, double time);

/// The yield over the substep [time, time + h], from the force of the substep before
/// (collider.yield.force): with u ≥ 0 the speed its keyframes approach along −a and
/// ℓ = F / F_max its load,
///   ṡ = u clamp(ℓ, 0, 1) + v_y clamp(ℓ − 1, −1, 1),   s ≥ 0,
/// so that at its limit it stands still (ṡ = u), past it backs off, and under it follows its
/// keyframes, slowed in proportion to its load, and comes back to them at up to v_y.
ColliderYield next_yield(const Collider& collider, double time, double h);

/// How far a yielding collider can stand from where its current offset and keyframes put it
/// after `span` seconds from `time` [m]: (u + v_y) span, a bound for the broad phase.
double yield_reach(const Collider& collider, double time, double span);

/// Signed distance φ (negative inside) and its gradient, the outward unit normal, at a point.
struct SignedDistance {
  double distance;
  Vec3 normal;
};

/// φ of the collider's shape at a point given in the collider's frame, in that frame's units.
SignedDistance local_signed_distance(const Collider& collider, const Vec3& local_point);

/// φ in world units (the pose's scale times the local φ) at a point given in the collider's
/// frame; the normal stays in that frame. The surface point under `local` is
/// local − (φ / scale) n.
inline SignedDistance posed_signed_distance(const Collider& collider, const ColliderKeyframe& pose,
                                            const Vec3& local) {
  SignedDistance d = local_signed_distance(collider, local);
  d.distance *= pose.scale;
  return d;
}

/// Throws std::invalid_argument naming the collider for sizes that are not positive and
/// finite, friction coefficients below zero or μ_k > μ_s, keyframe times not increasing or
/// keyframe scales that are not positive and finite, and a force limit, yield axis or yield speed
/// that is not positive, unit or finite.
void validate(const Collider& collider, int index);

}  // namespace rice::xpbd
