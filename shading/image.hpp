// A linear RGB image, row-major from the top-left pixel: what the renderer produces and
// the experiments write (PNG after tone mapping, OpenEXR as is).
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace rice::shading {

struct Image {
  int width = 0, height = 0;
  std::vector<Eigen::Array3f> pixels;  ///< width·height, linear radiance

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, Eigen::Array3f::Zero()) {}
  Eigen::Array3f& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const Eigen::Array3f& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// Root-mean-square difference over pixels and channels; throws std::invalid_argument when
/// the sizes differ.
double rms_difference(const Image& a, const Image& b);

/// Mean over pixels and channels (0 for an empty image).
double mean_radiance(const Image& image);

}  // namespace rice::shading
