// Writing rendered images: PNG after exposure, a filmic tone curve and the sRGB transfer
// function (for looking at), OpenEXR in linear float (for measuring and re-grading).
#pragma once

#include <filesystem>

#include "experiments/io/png_image.hpp"
#include "shading/image.hpp"

namespace rice::experiments {

/// The ACES filmic fit (Narkowicz 2015): radiance to a linear display value in [0, 1].
double aces_filmic(double radiance);

/// Linear radiance × 2^exposure through aces_filmic, then sRGB.
RgbImage tone_map(const shading::Image& image, double exposure);

/// Linear 32-bit float R, G, B channels, written atomically; throws std::runtime_error.
void write_exr(const std::filesystem::path& path, const shading::Image& image);

/// Reads an OpenEXR file's R, G, B channels as linear radiance (an environment image).
shading::Image read_exr(const std::filesystem::path& path);

}  // namespace rice::experiments
