// OpenEXR channels with a data window (experiments/io/render_images.hpp) and the crops of a
// frame joined (experiments/render/crop_merge.hpp): written and read back alike, two crops
// join into the frame, overlapping or missing pixels are refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "experiments/render/crop_merge.hpp"

namespace rice::experiments {
namespace {

/// Channels "R" and "depth.Z" of the pixels `data` of a 6 × 4 frame, each pixel's value its
/// index in the frame (and its negative).
ExrChannels crop_of(const shading::PixelWindow& data) {
  ExrChannels exr{6, 4, data, {{"R", {}}, {"depth.Z", {}}}};
  for (int y = data.y0; y < data.y1; ++y)
    for (int x = data.x0; x < data.x1; ++x) {
      exr.channels[0].second.push_back(static_cast<float>(y * 6 + x));
      exr.channels[1].second.push_back(-static_cast<float>(y * 6 + x));
    }
  return exr;
}

TEST(ExrChannels, ACropIsReadBackWithItsFrameAndDataWindow) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "rice_crop_round_trip.exr";
  write_exr(path, crop_of({2, 1, 5, 4}));
  const ExrChannels back = read_exr_channels(path);
  std::filesystem::remove(path);
  EXPECT_EQ(back.width, 6);
  EXPECT_EQ(back.height, 4);
  EXPECT_EQ(back.data.x0, 2);
  EXPECT_EQ(back.data.y1, 4);
  EXPECT_EQ(exr_channel(back, "depth.Z"), crop_of({2, 1, 5, 4}).channels[1].second);
  EXPECT_THROW(exr_channel(back, "G"), std::runtime_error);
}

TEST(MergeCrops, TwoCropsJoinIntoTheFrameAndGapsOrOverlapsAreRefused) {
  const ExrChannels frame = merge_crops({crop_of({0, 0, 6, 2}), crop_of({0, 2, 6, 4})}, "test");
  EXPECT_EQ(exr_channel(frame, "R"), crop_of({0, 0, 6, 4}).channels[0].second);
  EXPECT_EQ(exr_channel(frame, "depth.Z"), crop_of({0, 0, 6, 4}).channels[1].second);
  EXPECT_THROW(merge_crops({crop_of({0, 0, 6, 2})}, "test"), std::runtime_error);                           // a gap
  EXPECT_THROW(merge_crops({crop_of({0, 0, 6, 3}), crop_of({0, 2, 6, 4})}, "test"), std::runtime_error);  // overlap
  ExrChannels other = crop_of({0, 2, 6, 4});
  other.channels.pop_back();
  EXPECT_THROW(merge_crops({crop_of({0, 0, 6, 2}), other}, "test"), std::runtime_error);  // other channels
}

}  // namespace
}  // namespace rice::experiments
