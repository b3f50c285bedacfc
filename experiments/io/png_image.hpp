// 8-bit RGB images encoded as PNG (libpng) and written atomically.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
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

/// The PNG file's bytes; throws std::runtime_error where libpng fails (an empty image).
std::string encode_png(const RgbImage& image);

/// Writes `image` to `path` atomically (write_file_atomically); throws std::runtime_error.
void write_png(const std::filesystem::path& path, const RgbImage& image);

}  // namespace rice::experiments
