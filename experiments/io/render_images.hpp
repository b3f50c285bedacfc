// Writing rendered images: PNG after exposure, a filmic tone curve and the sRGB transfer
// function (for looking at), OpenEXR in linear float (for measuring and re-grading).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "experiments/io/png_image.hpp"
#include "shading/aovs.hpp"
#include "shading/image.hpp"
#include "shading/image_tiles.hpp"

namespace rice::experiments {

/// The ACES filmic fit (Narkowicz 2015): radiance to a linear display value in [0, 1].
double aces_filmic(double radiance);

/// Linear radiance × 2^exposure through aces_filmic, then sRGB.
RgbImage tone_map(const shading::Image& image, double exposure);

/// An OpenEXR image's 32-bit float channels by name ("R", "G", "B", then "layer.X" for the
/// AOVs), each a plane over the data window, row-major. The display window is the whole
/// frame (width × height); the data window is the part held, all of it or a crop.
struct ExrChannels {
  int width = 0, height = 0;
  shading::PixelWindow data;
  std::vector<std::pair<std::string, std::vector<float>>> channels;
};

/// The beauty image as R, G, B, and with `aovs` the layers normal.{X,Y,Z}, depth.Z,
/// albedo.{R,G,B} and grain_id.id; `data` places the image in a width × height frame
/// (empty: the image is the frame).
ExrChannels exr_channels(const shading::Image& image, const shading::Aovs* aovs = nullptr, int width = 0,
                         int height = 0, const shading::PixelWindow& data = {});

/// Writes the channels atomically; throws std::runtime_error.
void write_exr(const std::filesystem::path& path, const ExrChannels& exr);
/// Every channel of an OpenEXR file; throws std::runtime_error naming the file.
ExrChannels read_exr_channels(const std::filesystem::path& path);
/// A channel's plane; throws std::runtime_error naming the channel when it is not there.
const std::vector<float>& exr_channel(const ExrChannels& exr, const std::string& name);

/// Linear 32-bit float R, G, B channels, written atomically; throws std::runtime_error.
void write_exr(const std::filesystem::path& path, const shading::Image& image);

/// The R, G, B channels of the data window as an image; throws std::runtime_error when one
/// is missing.
shading::Image exr_beauty(const ExrChannels& exr);

/// Reads an OpenEXR file's R, G, B channels as linear radiance (an environment image).
shading::Image read_exr(const std::filesystem::path& path);

}  // namespace rice::experiments
