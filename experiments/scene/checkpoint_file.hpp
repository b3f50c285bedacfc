// A checkpoint file of a scene run (checkpoint.hpp says what it holds): a header naming the
// format's version and the scene it belongs to, then the state's bytes and their digest, so
// that another version, another scene, a truncated or a corrupted file is refused, saying which.
// File layout (the machine's byte order; read back by the same build):
//   "rice checkpoint\n"  16 bytes
//   version              u32    kCheckpointVersion
//   scene digest         u64    content_digest of the scene's text as run
//   frame                i32    the last frame stepped
//   state size           u64
//   state digest         u64    content_digest of the state's bytes
//   state                the parts' bytes (xpbd/state_archive.hpp)
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rice::experiments {

/// Bumped whenever what a part saves changes.
inline constexpr std::uint32_t kCheckpointVersion = 4;

struct Checkpoint {
  std::uint64_t scene_digest = 0;
  int frame = 0;      ///< the last frame stepped
  std::string state;  ///< the run's parts (checkpoint.hpp)
};

/// The bytes of a checkpoint file before its state: the magic and the header.
std::string checkpoint_header(std::uint64_t scene_digest, int frame, std::string_view state);

/// The bytes of a checkpoint file: its header, then its state.
std::string checkpoint_bytes(const Checkpoint& checkpoint);

/// The checkpoint in `bytes`, read from `source` (for messages). Throws std::runtime_error
/// starting with `source` and saying what is wrong: not a checkpoint, another version, another
/// scene (both digests), truncated or corrupted.
Checkpoint parse_checkpoint(std::string_view bytes, std::uint64_t scene_digest, const std::string& source);

/// RUN/checkpoint.bin: the run's last checkpoint.
std::filesystem::path checkpoint_path(const std::filesystem::path& run);

}  // namespace rice::experiments
