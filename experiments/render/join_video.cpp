// The parts of a video joined; see join_video.hpp.
#include "experiments/render/join_video.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/io/video.hpp"
#include "experiments/render/run_frames.hpp"

namespace rice::experiments {
namespace {

/// What the parts must share, from each part's run_info.txt.
std::string video_of(const std::filesystem::path& part) {
  const std::filesystem::path info = part / "run_info.txt";
  return "run " + run_info_value(info, "run_fps") + " fps, " + run_info_value(info, "width") + " x " +
         run_info_value(info, "height") + ", camera " + run_info_value(info, "camera_position_m") + " to " +
         run_info_value(info, "camera_target_m");
}

/// Each part's frames (frame_NNNN.png), by frame number; throws when a frame is in two parts.
std::map<int, std::filesystem::path> frames_of(const std::vector<std::filesystem::path>& parts) {
  std::map<int, std::filesystem::path> frames;
  for (const auto& part : parts)
    for (const auto& entry : std::filesystem::directory_iterator(part)) {
      const std::string name = entry.path().filename().string();
      if (!name.starts_with("frame_") || entry.path().extension() != ".png") continue;
      const int frame = frame_number(entry.path());
      if (!frames.emplace(frame, entry.path()).second)
        throw std::runtime_error("join-video: frame " + std::to_string(frame) + " is in two parts (" +
                                 frames[frame].parent_path().string() + " and " + part.string() + ")");
    }
  if (frames.empty()) throw std::runtime_error("join-video: the parts hold no frame_NNNN.png");
  const int first = frames.begin()->first, last = frames.rbegin()->first;
  if (last - first + 1 != static_cast<int>(frames.size()))
    throw std::runtime_error("join-video: frames " + std::to_string(first) + " to " + std::to_string(last) +
                             " have gaps: the parts hold " + std::to_string(frames.size()) + " of them");
  return frames;
}

}  // namespace

void validate(const JoinVideoSettings& s) {
  if (s.parts.empty()) throw std::invalid_argument("join-video: give the parts' folders");
  for (const auto& part : s.parts)
    if (!std::filesystem::is_regular_file(part / "run_info.txt"))
      throw std::invalid_argument("join-video: " + part.string() + " is not the folder of a rice render");
}

void join_video_command(const JoinVideoSettings& s, const std::filesystem::path& folder) {
  validate(s);
  const auto start = std::chrono::steady_clock::now();
  for (const auto& part : s.parts)
    if (video_of(part) != video_of(s.parts.front()))
      throw std::runtime_error("join-video: " + part.string() + " is of another video (" + video_of(part) +
                               ") than " + s.parts.front().string() + " (" + video_of(s.parts.front()) + ")");
  const std::map<int, std::filesystem::path> frames = frames_of(s.parts);
  make_output_folder(folder);
  for (const auto& [frame, png] : frames)
    for (const char* extension : {".png", ".exr"}) {
      const std::filesystem::path file = std::filesystem::path(png).replace_extension(extension);
      std::filesystem::copy_file(file, folder / file.filename(), std::filesystem::copy_options::overwrite_existing);
    }
  const std::filesystem::path info = s.parts.front() / "run_info.txt";
  const double fps = std::stod(run_info_value(info, "run_fps"));
  const int first = frames.begin()->first, count = static_cast<int>(frames.size());
  encode_video(folder, "frame_%04d.png", first, fps, "render.mp4");
  write_contact_sheet(folder, "frame_%04d.png", first, count, 12,
                      std::min(std::stoi(run_info_value(info, "width")), 320), "contact_sheet.png");
  std::string parts;
  for (const auto& part : s.parts) parts += (parts.empty() ? "" : " ") + part.string();
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "join-video"},
                                  {"parts", parts},
                                  {"frames", cell(first) + " " + cell(first + count - 1)},
                                  {"video", video_of(s.parts.front())},
                                  {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
