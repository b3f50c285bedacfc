// The pile at the end of a run (pile/): final_centres.csv (the grains released; those a fill
// found no room for stay out), the footprint radius, the groups of touching grains, the top
// centre, and pile.png, the centres from the top and the side with, on a plate, the heap's
// fitted flank and its angle of repose (heap_profile.csv); none in a mould.
#pragma once

#include <filesystem>

#include "experiments/pile/pile_plot.hpp"
#include "experiments/scene/observer.hpp"
#include "experiments/scene/scene.hpp"

namespace rice::experiments {

class PileObserver : public Observer {
 public:
  PileObserver(const std::filesystem::path& folder, const Scene& scene)
      : folder_(folder),
        holder_(scene.emitter.kind == EmitterKind::kFill       ? PileHolder::kMould
                : scene.container.kind == Container::kPlate ? PileHolder::kPlate
                                                            : PileHolder::kBowl),
        cohesion_(scene.effects.cohesion) {}
  void end(const World& world, const Stepper& stepper, SceneReport& report) override;

 private:
  std::filesystem::path folder_;
  PileHolder holder_;
  bool cohesion_;
};

}  // namespace rice::experiments
