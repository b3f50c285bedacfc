// What a moving collider carries at the end of a run: a paddle's portion, a scoop. The grains
// lying over a face of it that looks up, their centres within reach of it, counted once.
// Watched only in scenes with a collider that moves (keyframes); the count goes to
// run_info.txt as grains_carried.
#pragma once

#include <vector>

#include "experiments/scene/observer.hpp"
#include "experiments/scene/scene.hpp"
#include "xpbd/collider.hpp"

namespace rice::experiments {

/// Whether the collider moves: more than one keyframe.
bool moves(const xpbd::Collider& collider);

/// The centres within `reach` [m] of a collider that moves and is there at `time`, on the side of
/// a face whose outward normal points up (n_z > 1/2, so not the grains under a lid it presses).
int carried_grains(const std::vector<xpbd::Collider>& colliders, const std::vector<xpbd::Vec3>& centres,
                   double time, double reach);

class CarriedObserver : public Observer {
 public:
  void end(const World& world, const Stepper& stepper, SceneReport& report) override;
};

}  // namespace rice::experiments
