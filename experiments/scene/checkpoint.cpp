// A scene run's checkpoint; see checkpoint.hpp.
#include "experiments/scene/checkpoint.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "xpbd/state_archive.hpp"

namespace rice::experiments {
namespace {

/// Each part's state in turn: the grains released, the emitter, the solver, the observers.
template <class Archive>
void transfer_parts(Archive& archive, const RunParts& parts) {
  archive(parts.world.released);
  if constexpr (std::is_same_v<Archive, xpbd::StateWriter>) {
    parts.emitter.save_state(archive);
    parts.stepper.save_state(archive);
    for (const auto& observer : parts.observers) observer->save_state(archive);
  } else {
    parts.emitter.load_state(archive);
    parts.stepper.load_state(archive);
    for (const auto& observer : parts.observers) observer->load_state(archive);
  }
}

}  // namespace

void write_checkpoint(const std::filesystem::path& run, std::uint64_t scene_digest, int frame, const RunParts& parts) {
  xpbd::StateWriter out;
  transfer_parts(out, parts);
  const std::string& state = out.bytes();  // written after the header, not copied behind it
  const std::string header = checkpoint_header(scene_digest, frame, state);
  write_file_atomically(checkpoint_path(run), [&](std::ostream& file) {
    file.write(header.data(), static_cast<std::streamsize>(header.size()));
    file.write(state.data(), static_cast<std::streamsize>(state.size()));
  });
}

int resume_from_checkpoint(const std::filesystem::path& run, std::uint64_t scene_digest, const RunParts& parts) {
  const std::filesystem::path path = checkpoint_path(run);
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("--resume: " + path.string() + ": no checkpoint to resume from");
  std::stringstream bytes;
  bytes << file.rdbuf();
  const Checkpoint checkpoint = parse_checkpoint(bytes.str(), scene_digest, path.string());
  xpbd::StateReader in(checkpoint.state);
  try {
    transfer_parts(in, parts);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path.string() + ": does not fit this scene's world: " + e.what());
  }
  if (!in.at_end()) throw std::runtime_error(path.string() + ": does not fit this scene's world: bytes left over");
  return checkpoint.frame;
}

bool CheckpointClock::due(int frame) {
  const auto now = std::chrono::steady_clock::now();
  const bool due = every_ > 0 ? frame % every_ == 0 : now - last_ >= std::chrono::seconds(30);
  if (due) last_ = now;
  return due;
}

}  // namespace rice::experiments
