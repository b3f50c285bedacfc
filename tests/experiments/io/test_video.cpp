// The contact sheet (experiments/io/video.hpp): 12 frames spread evenly from the first to the
// last, 4 to a row, in order. Each frame is a flat grey that names it; the sheet is read back
// through ffmpeg as raw grey bytes and each tile's centre tells which frame it shows.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "experiments/io/child_process.hpp"
#include "experiments/io/png_image.hpp"
#include "experiments/io/video.hpp"

namespace rice::experiments {
namespace {

TEST(ContactSheet, TilesTwelveFramesFromTheFirstToTheLastInOrder) {
  const std::filesystem::path folder = std::filesystem::path(RICE_TEST_SCRATCH) / "contact-sheet";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const int count = 23, first = 5, width = 16, height = 8;
  for (int k = 0; k < count; ++k) {
    RgbImage frame(width, height);
    const auto grey = static_cast<std::uint8_t>(10 * k);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) frame.set(x, y, grey, grey, grey);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", first + k);
    write_png(folder / name, frame);
  }
  write_contact_sheet(folder, "frame_%04d.png", first, count, 12, width, "sheet.png");
  const ProgramRun raw = run_program(folder, {"ffmpeg", "-nostdin", "-loglevel", "error", "-i", "sheet.png", "-f",
                                              "rawvideo", "-pix_fmt", "gray", "-"});
  ASSERT_TRUE(raw.succeeded) << raw.err;
  const int padding = 4, sheet_width = 4 * width + 3 * padding;
  ASSERT_EQ(raw.out.size(), static_cast<size_t>(sheet_width) * (3 * height + 2 * padding));
  for (int tile = 0; tile < 12; ++tile) {
    const int x = (tile % 4) * (width + padding) + width / 2, y = (tile / 4) * (height + padding) + height / 2;
    const int grey = static_cast<unsigned char>(raw.out[static_cast<size_t>(y) * sheet_width + x]);
    EXPECT_NEAR(grey, 10 * 2 * tile, 2) << "tile " << tile << " shows frame " << grey / 10.0;  // frames 0, 2, .., 22
  }
  EXPECT_THROW(write_contact_sheet(folder, "missing_%04d.png", 1, 3, 12, width, "none.png"), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(folder / "none.png"));
}

}  // namespace
}  // namespace rice::experiments
