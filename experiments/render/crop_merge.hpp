// `rice merge-crops`: the crops of one frame (`rice render --crop`, each rendered by its own
// process, or on its own machine) joined into the frame. Each part's EXR places its pixels in
// the frame by its data window; a pixel depends only on the seed and its coordinates
// (shading/image_tiles.hpp), so the joined frame is the frame rendered whole, byte for byte.
// Every image name the parts share (render.exr, frame_NNNN.exr) is joined, with all its
// channels (the beauty image and the AOVs), into NAME.exr and NAME.png.
#pragma once

#include <filesystem>
#include <vector>

#include "experiments/io/render_images.hpp"

namespace rice::experiments {

struct MergeCropsSettings {
  std::vector<std::filesystem::path> parts;  ///< output folders of `rice render --crop`
  double exposure = 0.0;                     ///< stops, for the PNG
};

/// Throws std::invalid_argument for fewer than one part or a part that is not a folder.
void validate(const MergeCropsSettings& settings);

/// The crops joined. Throws std::runtime_error naming the part and the image when the parts'
/// frames or channels differ, two parts overlap, or pixels of the frame are in no part.
ExrChannels merge_crops(const std::vector<ExrChannels>& parts, const std::string& what);

/// Joins every EXR the parts share into `folder` (EXR and tone-mapped PNG) and writes
/// run_info.txt naming the parts.
void merge_crops_command(const MergeCropsSettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
