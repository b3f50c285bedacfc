// Analytic signed distances and keyframed motion of colliders; see collider.hpp.
#include "xpbd/collider.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rice::xpbd {
namespace {

SignedDistance sphere_distance(const Vec3& p, double radius) {
  const double length = p.norm();
  const Vec3 normal = length > 0.0 ? Vec3(p / length) : Vec3::UnitZ();
  return {length - radius, normal};
}

/// Box of half extents b: outside, the distance to the nearest point of the box; inside, minus
/// the distance to the nearest face.
SignedDistance box_distance(const Vec3& p, const Vec3& b) {
  const Vec3 q = p.cwiseAbs() - b;
  if ((q.array() > 0.0).any()) {
    const Vec3 outside = q.cwiseMax(0.0);
    const double distance = outside.norm();
    return {distance, outside.cwiseProduct(p.cwiseSign()) / distance};
  }
  int axis;
  const double distance = q.maxCoeff(&axis);
  Vec3 normal = Vec3::Zero();
  normal[axis] = p[axis] >= 0.0 ? 1.0 : -1.0;
  return {distance, normal};
}

ColliderKeyframe keyframed_pose(const Collider& collider, double time) {
  const auto& keys = collider.motion;
  if (time <= keys.front().time) return keys.front();
  if (time >= keys.back().time) return keys.back();
  const auto next = std::upper_bound(keys.begin(), keys.end(), time,
                                     [](double t, const ColliderKeyframe& k) { return t < k.time; });
  const ColliderKeyframe& a = *(next - 1);
  const ColliderKeyframe& b = *next;
  // Held between two equal poses: exactly that pose, so that the collider is at rest there
  // ((1 − s) a + s a differs from a in the last bit, and a collider in motion wakes what it
  // reaches).
  if (same_pose(a, b)) return {time, a.translation, a.rotation, a.scale};
  const double s = (time - a.time) / (b.time - a.time);
  const double scale = a.scale == b.scale ? a.scale : (1.0 - s) * a.scale + s * b.scale;  // (exactly 1 when unscaled)
  return {time, (1.0 - s) * a.translation + s * b.translation, a.rotation.slerp(s, b.rotation), scale};
}

/// u: the speed at which the keyframes move the collider along −a over [time, time + h].
double keyframed_approach(const Collider& collider, double time, double h) {
  const Vec3 step = keyframed_pose(collider, time + h).translation - keyframed_pose(collider, time).translation;
  return std::max(0.0, -step.dot(collider.yield_axis) / h);
}

}  // namespace

double yield_offset(const Collider& collider, double time) {
  if (!yields(collider)) return 0.0;
  return std::max(0.0, collider.yield.offset + collider.yield.rate * (time - collider.yield.time));
}

ColliderKeyframe collider_pose(const Collider& collider, double time) {
  ColliderKeyframe pose = keyframed_pose(collider, time);
  if (yields(collider)) pose.translation += yield_offset(collider, time) * collider.yield_axis;
  return pose;
}

ColliderYield next_yield(const Collider& collider, double time, double h) {
  const double s = yield_offset(collider, time);
  const double load = collider.yield.force / collider.force_limit;
  const double rate = keyframed_approach(collider, time, h) * std::clamp(load, 0.0, 1.0) +  // eq. in collider.hpp
                      collider.yield_speed * std::clamp(load - 1.0, -1.0, 1.0);
  return {time, s, std::max(rate, -s / h), collider.yield.force};  // back at its keyframes, not past them
}

double yield_reach(const Collider& collider, double time, double span) {
  const Vec3 step = keyframed_pose(collider, time + span).translation - keyframed_pose(collider, time).translation;
  return std::abs(step.dot(collider.yield_axis)) + collider.yield_speed * span;
}

SignedDistance local_signed_distance(const Collider& collider, const Vec3& p) {
  switch (collider.shape) {
    case ColliderShape::kHalfSpace:
      return {p.z(), Vec3::UnitZ()};
    case ColliderShape::kSphere:
      return sphere_distance(p, collider.radius);
    case ColliderShape::kBox:
      return box_distance(p, collider.half_extents);
    case ColliderShape::kCapsule: {
      const double z = std::clamp(p.z(), -collider.half_length, collider.half_length);
      return sphere_distance(p - Vec3(0.0, 0.0, z), collider.radius);
    }
    case ColliderShape::kDistanceGrid: {
      const GridSample s = sample(*collider.grid, p);
      return {s.distance, s.gradient};
    }
  }
  throw std::logic_error("local_signed_distance: unknown collider shape");
}

void validate(const Collider& c, int index) {
  const std::string name = "collider " + std::to_string(index);
  const auto positive = [](double value) { return std::isfinite(value) && value > 0.0; };
  const bool sizes_ok = c.shape == ColliderShape::kHalfSpace ||
                        (c.shape == ColliderShape::kSphere && positive(c.radius)) ||
                        (c.shape == ColliderShape::kBox && positive(c.half_extents.minCoeff()) &&
                         c.half_extents.allFinite()) ||
                        (c.shape == ColliderShape::kCapsule && positive(c.radius) && positive(c.half_length)) ||
                        (c.shape == ColliderShape::kDistanceGrid && c.grid);
  if (!sizes_ok) throw std::invalid_argument(name + ": its sizes must be positive and finite (a grid must be given)");
  if (c.shape == ColliderShape::kDistanceGrid) {
    try {
      validate(*c.grid);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + ": " + e.what());
    }
  }
  if (!(c.static_friction >= 0.0 && c.dynamic_friction >= 0.0 && c.dynamic_friction <= c.static_friction))
    throw std::invalid_argument(name + ": need 0 <= dynamic friction <= static friction, got " +
                                std::to_string(c.dynamic_friction) + " and " + std::to_string(c.static_friction));
  if (!(c.removal_time > 0.0)) throw std::invalid_argument(name + ": its removal time must be positive");
  if (c.motion.empty()) throw std::invalid_argument(name + ": needs at least one keyframe");
  for (size_t k = 0; k < c.motion.size(); ++k) {
    const ColliderKeyframe& key = c.motion[k];
    if (!std::isfinite(key.time) || !key.translation.allFinite() || !key.rotation.coeffs().allFinite() ||
        std::abs(key.rotation.norm() - 1.0) > 1e-9 || !(std::isfinite(key.scale) && key.scale > 0.0))
      throw std::invalid_argument(name + ": keyframe " + std::to_string(k) +
                                  " needs a finite time and translation, a unit rotation and a positive scale");
    if (k > 0 && !(key.time > c.motion[k - 1].time))
      throw std::invalid_argument(name + ": keyframe times must increase (keyframe " + std::to_string(k) + ")");
  }
  if (!(c.force_limit > 0.0) || !(std::abs(c.yield_axis.norm() - 1.0) < 1e-9) ||
      !(std::isfinite(c.yield_speed) && c.yield_speed > 0.0))
    throw std::invalid_argument(name + ": needs a positive force limit, a unit yield axis and a positive, finite "
                                "yield speed");
}

}  // namespace rice::xpbd
