// Frames to an MP4 by ffmpeg; see video.hpp.
#include "experiments/io/video.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/io/child_process.hpp"
#include "experiments/io/interrupt.hpp"

namespace rice::experiments {

void encode_video(const std::filesystem::path& folder, const std::string& pattern, int first, double fps,
                  const std::string& name) {
  set_activity("video " + name);
  const std::string partial = "." + name + ".partial";  // renamed into place once whole
  // An even size: yuv420p halves the chroma planes, and libx264 refuses odd dimensions.
  const std::vector<std::string> argv = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error",
                                         "-framerate", std::to_string(fps), "-start_number", std::to_string(first),
                                         "-i", pattern, "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                         "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18",
                                         "-movflags", "+faststart", "-f", "mp4", partial};
  const ProgramRun run = run_program(folder, argv);
  if (!run.started)
    throw std::runtime_error("video: ffmpeg is not installed or could not start (Debian package ffmpeg)");
  if (!run.succeeded) {
    std::filesystem::remove(folder / partial);
    throw std::runtime_error("video: ffmpeg failed on " + (folder / pattern).string() + ": " + run.err);
  }
  std::filesystem::rename(folder / partial, folder / name);
}

}  // namespace rice::experiments
