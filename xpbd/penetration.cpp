// Deepest overlaps; see penetration.hpp.
#include "xpbd/penetration.hpp"

#include <algorithm>
#include <cmath>

#include "xpbd/body.hpp"
#include "xpbd/collider.hpp"

namespace rice::xpbd {

std::vector<PlacedSpheres> placed_spheres(const Model& model) {
  std::vector<PlacedSpheres> placed(model.bodies.size());
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    PlacedSpheres& p = placed[b];
    for (int s = 0; s < body.sphere_count(); ++s) {
      p.centres.push_back(sphere_centre(model, body, s));
      p.radii.push_back(sphere_radius(model, body, s));
      p.box.lower = p.box.lower.cwiseMin(p.centres[s] - Vec3::Constant(p.radii[s]));
      p.box.upper = p.box.upper.cwiseMax(p.centres[s] + Vec3::Constant(p.radii[s]));
    }
  }
  return placed;
}

Penetration deepest_penetration(const Model& model, double time) {
  const std::vector<PlacedSpheres> placed = placed_spheres(model);
  std::vector<Box> boxes;
  for (const PlacedSpheres& p : placed) boxes.push_back(p.box);
  Penetration deepest;
  for (const auto& [a, b] : overlapping_pairs(boxes)) {
    const PlacedSpheres &pa = placed[a], &pb = placed[b];
    for (size_t i = 0; i < pa.centres.size(); ++i)
      for (size_t j = 0; j < pb.centres.size(); ++j)
        deepest.between_bodies = std::max(deepest.between_bodies,
                                          pa.radii[i] + pb.radii[j] - (pa.centres[i] - pb.centres[j]).norm());
  }
  for (const Collider& collider : model.colliders) {
    if (!collider_present(collider, time)) continue;
    const ColliderKeyframe pose = collider_pose(collider, time);
    for (const PlacedSpheres& p : placed)
      for (size_t i = 0; i < p.centres.size(); ++i) {
        const double phi = posed_signed_distance(collider, pose, to_local(pose, p.centres[i])).distance;
        deepest.into_colliders = std::max(deepest.into_colliders, p.radii[i] - phi);
      }
  }
  return deepest;
}

}  // namespace rice::xpbd
