// Frames to a video a browser or a slide plays: H.264 in MP4, yuv420p (what every player
// decodes), CRF 18 (visually lossless for these renders), the index at the front (faststart,
// so a web page can start playing before it has it all), encoded by ffmpeg (Debian's ffmpeg);
// and a contact sheet: frames spread over the run, tiled into one PNG by ffmpeg's tile filter.
#pragma once

#include <filesystem>
#include <string>

namespace rice::experiments {

/// Encodes `folder`/<pattern> (a printf pattern such as "frame_%04d.png", numbered from
/// `first`) at `fps` into `folder`/`name`, written atomically. Throws std::runtime_error when
/// ffmpeg is missing or fails, with its message.
void encode_video(const std::filesystem::path& folder, const std::string& pattern, int first, double fps,
                  const std::string& name);

/// Tiles `tiles` frames of `folder`/<pattern> (numbered `first` .. `first` + `count` - 1),
/// evenly spread and each scaled to `tile_width` pixels wide, into `folder`/`name`, a PNG
/// ceil(tiles / 4) rows of 4 (fewer columns with fewer frames); written atomically. Throws
/// std::runtime_error when ffmpeg is missing or fails.
void write_contact_sheet(const std::filesystem::path& folder, const std::string& pattern, int first, int count,
                         int tiles, int tile_width, const std::string& name);

}  // namespace rice::experiments
