// A scene run's checkpoint, for `rice run --resume`: everything the next frame depends on,
// taken at the end of a frame. That is the model's positions, velocities, rigid poses and
// sleep, the solver's warm starts and contact states (anchors, sliding, bonds and broken
// pairs), the grains released, the emitter's random stream and rounds, the observers' tallies
// and the frame number (each part's save_state says what it holds). The scene itself is not
// in it: the run rebuilds the same world from the same scene file and seed, and the header's
// digest of that file (with its --set overrides) makes sure it is the same (checkpoint_file.hpp).
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "experiments/scene/checkpoint_file.hpp"
#include "experiments/scene/emitter.hpp"
#include "experiments/scene/observer.hpp"
#include "experiments/scene/stepper.hpp"
#include "experiments/scene/world.hpp"

namespace rice::experiments {

/// The parts of a run whose state a checkpoint holds.
struct RunParts {
  World& world;
  Emitter& emitter;
  Stepper& stepper;
  std::vector<std::unique_ptr<Observer>>& observers;
};

/// Writes RUN/checkpoint.bin atomically at the end of `frame`.
void write_checkpoint(const std::filesystem::path& run, std::uint64_t scene_digest, int frame, const RunParts& parts);

/// Loads the parts from RUN/checkpoint.bin and returns its frame. Throws std::runtime_error
/// for a run without one, or one that parse_checkpoint or the parts refuse.
int resume_from_checkpoint(const std::filesystem::path& run, std::uint64_t scene_digest, const RunParts& parts);

/// When the next checkpoint is due: every `every` frames, or (0) at the first frame's end 30 s
/// of wall time after the last.
class CheckpointClock {
 public:
  explicit CheckpointClock(int every) : every_(every) {}
  bool due(int frame);

 private:
  int every_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace rice::experiments
