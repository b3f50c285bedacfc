// Each frame's poses, frames/frame_NNNN.csv: for rigid grains a row per grain, its centre c and
// its rotation q since the start (world = q (p₀ − c₀) + c); for soft grains a row per
// simulation vertex. `in_scene` is 0 for the grains still parked far away (not yet emitted, or
// a fill found no room for them), which a render leaves out.
#pragma once

#include <filesystem>

#include "experiments/scene/observer.hpp"

namespace rice::experiments {

class FramesObserver : public Observer {
 public:
  explicit FramesObserver(const std::filesystem::path& folder) : folder_(folder / "frames") {}
  void begin(const World& world) override;
  void observe(const World& world, const Stepper& stepper, int frame, double wall_seconds) override;

 private:
  std::filesystem::path folder_;
};

}  // namespace rice::experiments
