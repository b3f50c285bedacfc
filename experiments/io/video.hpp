// Frames to a video a browser or a slide plays: H.264 in MP4, yuv420p (what every player
// decodes), CRF 18 (visually lossless for these renders), the index at the front (faststart,
// so a web page can start playing before it has it all), encoded by ffmpeg (Debian's ffmpeg).
#pragma once

#include <filesystem>
#include <string>

namespace rice::experiments {

/// Encodes `folder`/<pattern> (a printf pattern such as "frame_%04d.png", numbered from
/// `first`) at `fps` into `folder`/`name`, written atomically. Throws std::runtime_error when
/// ffmpeg is missing or fails, with its message.
void encode_video(const std::filesystem::path& folder, const std::string& pattern, int first, double fps,
                  const std::string& name);

}  // namespace rice::experiments
