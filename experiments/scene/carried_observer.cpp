// The grains a moving collider carries; see carried_observer.hpp.
#include "experiments/scene/carried_observer.hpp"

#include "experiments/io/csv_table.hpp"

namespace rice::experiments {

bool moves(const xpbd::Collider& collider) { return collider.motion.size() > 1; }

namespace {

bool carries(const xpbd::Collider& collider, const xpbd::Vec3& centre, double time, double reach) {
  if (!moves(collider) || !xpbd::collider_present(collider, time)) return false;
  const xpbd::ColliderKeyframe pose = xpbd::collider_pose(collider, time);
  const xpbd::SignedDistance d = xpbd::posed_signed_distance(collider, pose, xpbd::to_local(pose, centre));
  return d.distance < reach && (pose.rotation * d.normal).z() > 0.5;
}

}  // namespace

int carried_grains(const std::vector<xpbd::Collider>& colliders, const std::vector<xpbd::Vec3>& centres,
                   double time, double reach) {
  int carried = 0;
  for (const xpbd::Vec3& centre : centres) {
    bool on_one = false;
    for (const xpbd::Collider& collider : colliders) on_one = on_one || carries(collider, centre, time, reach);
    carried += on_one;
  }
  return carried;
}

void CarriedObserver::end(const World& world, const Stepper& stepper, SceneReport& report) {
  // Two grain lengths: a portion two or three grains deep.
  const int carried =
      carried_grains(world.model.colliders, world.released_centres(), stepper.time(), 2.0 * world.grain_length);
  report.info.push_back({"grains_carried", cell(carried)});
}

}  // namespace rice::experiments
