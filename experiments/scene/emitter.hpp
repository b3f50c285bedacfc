// Emitters bring a scene's grains into it over time ([emitter] kind): before the bodies are
// made, an emitter lays out where each grain is built; then, frame by frame, it releases the
// grains that are due from their parking places into the scene. The kinds are listed in
// scene_parts.cpp: spout (spout_emitter.hpp), clump (clump_emitter.hpp), fill
// (fill_emitter.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "experiments/scene/world.hpp"
#include "xpbd/state_archive.hpp"

namespace rice::experiments {

/// Lines of run_info.txt: key, value.
using RunInfoEntries = std::vector<std::pair<std::string, std::string>>;

class Emitter {
 public:
  virtual ~Emitter() = default;

  /// Before the bodies are made (the world has its variants, instances, grain length and
  /// colliders): sets world.drops, one build point per grain, and world.parking_row; may turn
  /// the instances. Throws std::invalid_argument for a scene it cannot emit.
  virtual void lay_out(World& world) = 0;

  /// Before the frame that starts at `time`: releases the grains due.
  virtual void emit(World& world, double time) = 0;

  /// After the run: what it did, for run_info.txt.
  virtual void report(const World& world, RunInfoEntries& info) const = 0;

  /// What it carries between frames beyond world.released, for checkpoints; none by default.
  virtual void save_state(xpbd::StateWriter&) const {}
  virtual void load_state(xpbd::StateReader&) {}
};

}  // namespace rice::experiments
