// `rice join-video`: the parts of one video (`rice render --every-frame --frames FIRST LAST`,
// each rendered by its own process or cluster job, all with the whole video's camera) joined
// into one folder: every frame's PNG and EXR, render.mp4 and contact_sheet.png (io/video.hpp),
// as `rice render --every-frame --video` makes them in one process.
#pragma once

#include <filesystem>
#include <vector>

namespace rice::experiments {

struct JoinVideoSettings {
  std::vector<std::filesystem::path> parts;  ///< output folders of `rice render --every-frame --frames`
};

/// Throws std::invalid_argument for no parts or a part that is not a folder with run_info.txt.
void validate(const JoinVideoSettings& settings);

/// Copies the parts' frames into `folder` and encodes them. Throws std::runtime_error naming
/// the part when parts are of other runs or sizes, or when their frames are not each frame of
/// one range once.
void join_video_command(const JoinVideoSettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
