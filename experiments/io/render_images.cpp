// Image output of the renderer; see render_images.hpp.
#include "experiments/io/render_images.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"

namespace rice::experiments {
namespace {

double srgb_encode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace

double aces_filmic(double x) { return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }

RgbImage tone_map(const shading::Image& image, double exposure) {
  RgbImage out(image.width, image.height);
  const double scale = std::exp2(exposure);
  auto byte = [&](float v) {
    return static_cast<std::uint8_t>(std::lround(255.0 * srgb_encode(aces_filmic(std::max(0.0, scale * v)))));
  };
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto& p = image.at(x, y);
      out.set(x, y, byte(p[0]), byte(p[1]), byte(p[2]));
    }
  return out;
}

void write_exr(const std::filesystem::path& path, const shading::Image& image) {
  if (image.width < 1 || image.height < 1) throw std::runtime_error("write_exr: empty image for " + path.string());
  std::ostringstream bytes;
  try {
    Imf::StdOSStream stream;
    Imf::Header header(image.width, image.height);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(stream, header);
    Imf::FrameBuffer frame;
    const std::size_t pixel = sizeof(Eigen::Array3f), row = pixel * image.width;
    char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
    frame.insert("R", Imf::Slice(Imf::FLOAT, base, pixel, row));
    frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), pixel, row));
    frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), pixel, row));
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
    bytes << stream.str();
  } catch (const std::exception& e) {
    throw std::runtime_error("write_exr: " + path.string() + ": " + e.what());
  }
  write_file_atomically(path, bytes.str());
}

shading::Image read_exr(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    shading::Image image(width, height);
    Imf::FrameBuffer frame;
    const std::size_t pixel = sizeof(Eigen::Array3f), row = pixel * width;
    char* base = reinterpret_cast<char*>(image.pixels.data()) - (window.min.x * pixel + window.min.y * row);
    for (int c = 0; c < 3; ++c)
      frame.insert(std::string(1, "RGB"[c]), Imf::Slice(Imf::FLOAT, base + c * sizeof(float), pixel, row, 1, 1, 0.0));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& e) {
    throw std::runtime_error("read_exr: " + path.string() + ": " + e.what());
  }
}

}  // namespace rice::experiments
