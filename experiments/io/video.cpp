// Frames to an MP4 and to a contact sheet by ffmpeg; see video.hpp.
#include "experiments/io/video.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/io/child_process.hpp"
#include "experiments/io/interrupt.hpp"

namespace rice::experiments {

namespace {

// Runs ffmpeg in `folder` with `arguments`, writing the hidden "." + name + ".partial",
// renamed to `name` once ffmpeg has succeeded; `what` starts the error messages.
void run_ffmpeg(const std::filesystem::path& folder, const std::vector<std::string>& arguments,
                const std::string& name, const std::string& what) {
  const std::string partial = "." + name + ".partial";
  std::vector<std::string> argv = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error"};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  argv.push_back(partial);
  const ProgramRun run = run_program(folder, argv);
  if (!run.started)
    throw std::runtime_error(what + ": ffmpeg is not installed or could not start (Debian package ffmpeg)");
  if (!run.succeeded) {
    std::filesystem::remove(folder / partial);
    throw std::runtime_error(what + ": ffmpeg failed in " + folder.string() + ": " + run.err);
  }
  std::filesystem::rename(folder / partial, folder / name);
}

}  // namespace

void encode_video(const std::filesystem::path& folder, const std::string& pattern, int first, double fps,
                  const std::string& name) {
  set_activity("video " + name);
  // An even size: yuv420p halves the chroma planes, and libx264 refuses odd dimensions.
  run_ffmpeg(folder,
             {"-framerate", std::to_string(fps), "-start_number", std::to_string(first), "-i", pattern, "-vf",
              "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-movflags",
              "+faststart", "-f", "mp4"},
             name, "video");
}

void write_contact_sheet(const std::filesystem::path& folder, const std::string& pattern, int first, int count,
                         int tiles, int tile_width, const std::string& name) {
  set_activity("contact sheet " + name);
  tiles = std::max(1, std::min(tiles, count));
  const int columns = std::min(tiles, 4);
  const int rows = (tiles + columns - 1) / columns;
  // Frame n (from 0) is kept when n + 1/2 lies in [k s, k s + 1) for some k, s = (count - 1) /
  // (tiles - 1): one frame per k, the first and the last among them.
  const double step = tiles > 1 ? static_cast<double>(count - 1) / (tiles - 1) : static_cast<double>(count);
  const std::string keep = "select='lt(mod(n+0.5\\," + std::to_string(step) + ")\\,1)'";
  const std::string tile = "tile=" + std::to_string(columns) + "x" + std::to_string(rows) + ":padding=4:color=white";
  run_ffmpeg(folder,
             {"-start_number", std::to_string(first), "-i", pattern, "-vf",
              keep + ",scale=" + std::to_string(tile_width) + ":-2," + tile, "-frames:v", "1", "-update", "1", "-f",
              "image2", "-c:v", "png"},
             name, "contact sheet");
}

}  // namespace rice::experiments
