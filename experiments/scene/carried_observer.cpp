// The grains a moving collider carries; see carried_observer.hpp.
#include "experiments/scene/carried_observer.hpp"

#include <algorithm>

#include "experiments/io/csv_table.hpp"

namespace rice::experiments {

bool moves(const xpbd::Collider& collider) { return collider.motion.size() > 1; }

int carried_grains(const std::vector<xpbd::Collider>& colliders, const std::vector<xpbd::Vec3>& centres,
                   double time, double reach) {
  std::vector<bool> carried(centres.size(), false);
  for (const xpbd::Collider& collider : colliders) {
    if (!moves(collider) || !xpbd::collider_present(collider, time)) continue;
    const xpbd::ColliderKeyframe pose = xpbd::collider_pose(collider, time);
    for (size_t g = 0; g < centres.size(); ++g) {
      const xpbd::SignedDistance d = xpbd::posed_signed_distance(collider, pose, xpbd::to_local(pose, centres[g]));
      carried[g] = carried[g] || (d.distance < reach && (pose.rotation * d.normal).z() > 0.5);
    }
  }
  return static_cast<int>(std::count(carried.begin(), carried.end(), true));
}

void CarriedObserver::end(const World& world, const Stepper& stepper, SceneReport& report) {
  // Two grain lengths: a portion two or three grains deep.
  const int carried =
      carried_grains(world.model.colliders, world.released_centres(), stepper.time(), 2.0 * world.grain_length);
  report.info.push_back({"grains_carried", cell(carried)});
}

}  // namespace rice::experiments
