// Joining crops of a frame; see crop_merge.hpp.
#include "experiments/render/crop_merge.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/run_info.hpp"

namespace rice::experiments {
namespace {

std::vector<std::string> channel_names(const ExrChannels& exr) {
  std::vector<std::string> names;
  for (const auto& [name, plane] : exr.channels) names.push_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

/// The EXR file names in a part's folder.
std::set<std::string> exr_names(const std::filesystem::path& part) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(part))
    if (entry.path().extension() == ".exr") names.insert(entry.path().filename().string());
  return names;
}

}  // namespace

void validate(const MergeCropsSettings& s) {
  if (s.parts.empty()) throw std::invalid_argument("merge-crops: give the output folders of `rice render --crop`");
  for (const auto& part : s.parts)
    if (!std::filesystem::is_directory(part))
      throw std::invalid_argument("merge-crops: " + part.string() + " is not a folder");
}

ExrChannels merge_crops(const std::vector<ExrChannels>& parts, const std::string& what) {
  if (parts.empty()) throw std::runtime_error("merge-crops: " + what + ": no parts");
  const ExrChannels& first = parts.front();
  ExrChannels frame{first.width, first.height, {0, 0, first.width, first.height}, {}};
  const std::size_t n = static_cast<std::size_t>(frame.width) * frame.height;
  for (const std::string& name : channel_names(first)) frame.channels.emplace_back(name, std::vector<float>(n, 0.0f));
  std::vector<int> owner(n, -1);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const ExrChannels& part = parts[k];
    const std::string which = what + " part " + std::to_string(k + 1);
    if (part.width != frame.width || part.height != frame.height)
      throw std::runtime_error("merge-crops: " + which + " is of a " + std::to_string(part.width) + " x " +
                               std::to_string(part.height) + " frame, part 1 of " + std::to_string(frame.width) +
                               " x " + std::to_string(frame.height));
    if (channel_names(part) != channel_names(first))
      throw std::runtime_error("merge-crops: " + which + " holds other channels than part 1");
    std::vector<const std::vector<float>*> source;  // in the frame's channel order
    for (const auto& [name, plane] : frame.channels) source.push_back(&exr_channel(part, name));
    const shading::PixelWindow& d = part.data;
    for (int y = d.y0; y < d.y1; ++y)
      for (int x = d.x0; x < d.x1; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * frame.width + x;
        if (owner[i] >= 0)
          throw std::runtime_error("merge-crops: " + which + " and part " + std::to_string(owner[i] + 1) +
                                   " both hold pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")");
        owner[i] = static_cast<int>(k);
        const std::size_t j = static_cast<std::size_t>(y - d.y0) * d.width() + (x - d.x0);
        for (std::size_t c = 0; c < source.size(); ++c) frame.channels[c].second[i] = (*source[c])[j];
      }
  }
  const auto missing = std::count(owner.begin(), owner.end(), -1);
  if (missing > 0)
    throw std::runtime_error("merge-crops: " + what + ": " + std::to_string(missing) + " of the frame's " +
                             std::to_string(n) + " pixels are in no part");
  return frame;
}

void merge_crops_command(const MergeCropsSettings& s, const std::filesystem::path& folder) {
  validate(s);
  const std::set<std::string> names = exr_names(s.parts.front());
  if (names.empty()) throw std::runtime_error("merge-crops: " + s.parts.front().string() + " holds no .exr");
  make_output_folder(folder);
  std::string parts;
  for (const std::string& name : names) {
    std::vector<ExrChannels> crops;
    for (const auto& part : s.parts) {
      if (!std::filesystem::exists(part / name))
        throw std::runtime_error("merge-crops: " + part.string() + " has no " + name);
      crops.push_back(read_exr_channels(part / name));
    }
    const ExrChannels frame = merge_crops(crops, name);
    write_exr(folder / name, frame);
    write_png(folder / std::filesystem::path(name).replace_extension(".png"), tone_map(exr_beauty(frame), s.exposure));
  }
  for (const auto& part : s.parts) parts += (parts.empty() ? "" : " ") + part.string();
  write_file_atomically(folder / "run_info.txt", run_info({{"command", "merge-crops"},
                                                           {"parts", parts},
                                                           {"images", std::to_string(names.size())}}));
  std::printf("merge-crops: %zu image(s) from %zu parts into %s\n", names.size(), s.parts.size(), folder.c_str());
}

}  // namespace rice::experiments
