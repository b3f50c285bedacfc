// Observers watch a scene run (scene_run.hpp) and write what it shows: called once before
// the first frame, after every frame, and once at the end, when each writes its files and adds
// its measures to the run's result and its lines to run_info.txt. Which observers watch a
// scene is listed in scene_parts.cpp; adding one is one new file and one line there.
#pragma once

#include <cstdio>
#include <string>

#include "experiments/scene/emitter.hpp"
#include "experiments/scene/scene_result.hpp"
#include "experiments/scene/stepper.hpp"
#include "experiments/scene/world.hpp"

namespace rice::experiments {

/// What the end of a run gathers: the measures and the run_info.txt lines.
struct SceneReport {
  SceneResult result;
  RunInfoEntries info;
};

class Observer {
 public:
  virtual ~Observer() = default;
  /// Before the first frame, once every grain is built (parked).
  virtual void begin(const World&) {}
  /// After frame `frame` (1 for the first) was stepped in `wall_seconds`.
  virtual void observe(const World&, const Stepper&, int /*frame*/, double /*wall_seconds*/) {}
  /// After the last frame.
  virtual void end(const World&, const Stepper&, SceneReport&) {}
  /// What it gathered over the frames so far, for checkpoints; none by default (an observer
  /// that writes each frame's files as it goes keeps nothing).
  virtual void save_state(xpbd::StateWriter&) const {}
  virtual void load_state(xpbd::StateReader&) {}
};

/// "frame_0001" for frame 1: the stem of a frame's files.
inline std::string frame_name(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d", frame);
  return name;
}

}  // namespace rice::experiments
