// Deepest overlaps; see penetration.hpp.
#include "xpbd/penetration.hpp"

#include <algorithm>
#include <cmath>

#include "xpbd/body.hpp"
#include "xpbd/broad_phase.hpp"
#include "xpbd/collider.hpp"

namespace rice::xpbd {

Penetration deepest_penetration(const Model& model, double time) {
  const int n = static_cast<int>(model.bodies.size());
  std::vector<std::vector<Vec3>> centres(n);
  std::vector<std::vector<double>> radii(n);
  std::vector<Box> boxes(n);
  for (int b = 0; b < n; ++b) {
    const Body& body = model.bodies[b];
    boxes[b] = {Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
    for (int s = 0; s < body.sphere_count(); ++s) {
      centres[b].push_back(sphere_centre(model, body, s));
      radii[b].push_back(sphere_radius(model, body, s));
      boxes[b].lower = boxes[b].lower.cwiseMin(centres[b][s] - Vec3::Constant(radii[b][s]));
      boxes[b].upper = boxes[b].upper.cwiseMax(centres[b][s] + Vec3::Constant(radii[b][s]));
    }
  }
  Penetration deepest;
  for (const auto& [a, b] : overlapping_pairs(boxes))
    for (size_t i = 0; i < centres[a].size(); ++i)
      for (size_t j = 0; j < centres[b].size(); ++j)
        deepest.between_bodies = std::max(deepest.between_bodies,
                                          radii[a][i] + radii[b][j] - (centres[a][i] - centres[b][j]).norm());
  for (const Collider& collider : model.colliders) {
    const ColliderKeyframe pose = collider_pose(collider, time);
    for (int b = 0; b < n; ++b)
      for (size_t i = 0; i < centres[b].size(); ++i) {
        const Vec3 local = pose.rotation.conjugate() * (centres[b][i] - pose.translation);
        deepest.into_colliders =
            std::max(deepest.into_colliders, radii[b][i] - local_signed_distance(collider, local).distance);
      }
  }
  return deepest;
}

}  // namespace rice::xpbd
