// A checkpoint file; see checkpoint_file.hpp.
#include "experiments/scene/checkpoint_file.hpp"

#include <sstream>
#include <stdexcept>

#include "experiments/io/content_digest.hpp"
#include "xpbd/state_archive.hpp"

namespace rice::experiments {
namespace {

constexpr std::string_view kMagic = "rice checkpoint\n";

/// The fixed part after the magic.
struct CheckpointHeader {
  std::uint32_t version = kCheckpointVersion;
  std::uint64_t scene_digest = 0;
  std::int32_t frame = 0;
  std::uint64_t state_size = 0;
  std::uint64_t state_digest = 0;
};

/// The header's fields one after the other, without the struct's padding.
template <class Archive, class Header>
void transfer_header(Archive& archive, Header& h) {
  archive(h.version, h.scene_digest, h.frame, h.state_size, h.state_digest);
}

constexpr std::size_t kHeaderSize = kMagic.size() + 4 + 8 + 4 + 8 + 8;

std::string hex(std::uint64_t value) {
  std::ostringstream out;
  out << std::hex << value;
  return out.str();
}

}  // namespace

std::string checkpoint_header(std::uint64_t scene_digest, int frame, std::string_view state) {
  CheckpointHeader header;
  header.scene_digest = scene_digest;
  header.frame = frame;
  header.state_size = state.size();
  header.state_digest = content_digest(state);
  xpbd::StateWriter out;
  transfer_header(out, header);
  return std::string(kMagic) + out.bytes();
}

std::string checkpoint_bytes(const Checkpoint& checkpoint) {
  return checkpoint_header(checkpoint.scene_digest, checkpoint.frame, checkpoint.state) + checkpoint.state;
}

Checkpoint parse_checkpoint(std::string_view bytes, std::uint64_t scene_digest, const std::string& source) {
  const auto refuse = [&](const std::string& why) { throw std::runtime_error(source + ": " + why); };
  if (bytes.substr(0, kMagic.size()) != kMagic) refuse("not a rice checkpoint");
  if (bytes.size() < kHeaderSize) refuse("truncated: it ends inside its header");
  CheckpointHeader header;
  xpbd::StateReader in(bytes.substr(kMagic.size(), kHeaderSize - kMagic.size()));
  transfer_header(in, header);
  if (header.version != kCheckpointVersion)
    refuse("written as checkpoint version " + std::to_string(header.version) + "; this build reads version " +
           std::to_string(kCheckpointVersion));
  if (header.scene_digest != scene_digest)
    refuse("from another scene: its scene digest is " + hex(header.scene_digest) + ", this scene's " +
           hex(scene_digest) + " (the scene file or its --set overrides differ)");
  const std::string_view state = bytes.substr(kHeaderSize);
  if (state.size() != header.state_size)
    refuse("truncated: its state has " + std::to_string(state.size()) + " of " + std::to_string(header.state_size) +
           " bytes");
  if (content_digest(state) != header.state_digest) refuse("corrupted: its state does not match its digest");
  if (header.frame < 0) refuse("corrupted: frame " + std::to_string(header.frame));
  return {header.scene_digest, header.frame, std::string(state)};
}

std::filesystem::path checkpoint_path(const std::filesystem::path& run) { return run / "checkpoint.bin"; }

}  // namespace rice::experiments
