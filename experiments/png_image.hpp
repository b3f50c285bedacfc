// 8-bit RGB images written as PNG (libpng), through a temporary name and a rename.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rice::experiments {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  ///< row-major, top row first, 3 bytes a pixel
  RgbImage(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(3) * w * h, 0) {}
  void set(int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    std::uint8_t* p = &pixels[3 * (static_cast<size_t>(y) * width + x)];
    p[0] = r;
    p[1] = g;
    p[2] = b;
  }
};

/// Writes `image` to `path`; throws std::runtime_error naming the path on failure.
void write_png(const std::filesystem::path& path, const RgbImage& image);

}  // namespace rice::experiments
