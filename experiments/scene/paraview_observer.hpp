// The run for ParaView ([effects] paraview): each frame's grains as points in
// paraview/frame_NNNN.vtp (VTK XML poly data), with their velocity, whether they are awake,
// how many other grains each is bonded to, and whether it is in the scene yet; grains.pvd
// collects the frames with their times, so ParaView opens the run as one time series. Off by
// default, and then it costs nothing.
#pragma once

#include <filesystem>

#include "experiments/scene/observer.hpp"

namespace rice::experiments {

class ParaviewObserver : public Observer {
 public:
  ParaviewObserver(const std::filesystem::path& folder, double fps) : folder_(folder), fps_(fps) {}
  void begin(const World& world) override;
  void observe(const World& world, const Stepper& stepper, int frame, double wall_seconds) override;
  void end(const World& world, const Stepper& stepper, SceneReport& report) override;

 private:
  std::filesystem::path folder_;
  double fps_;
  int last_frame_ = 0;
};

}  // namespace rice::experiments
