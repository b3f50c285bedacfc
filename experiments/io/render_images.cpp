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

ExrChannels exr_channels(const shading::Image& image, const shading::Aovs* aovs, int width, int height,
                         const shading::PixelWindow& data) {
  ExrChannels exr{width, height, data, {}};
  if (data.empty()) exr = {image.width, image.height, {0, 0, image.width, image.height}, {}};
  const std::size_t n = image.pixels.size();
  const auto add = [&](const std::string& name, auto&& value) {
    std::vector<float>& plane = exr.channels.emplace_back(name, std::vector<float>(n)).second;
    for (std::size_t i = 0; i < n; ++i) plane[i] = value(i);
  };
  for (int c = 0; c < 3; ++c) add(std::string(1, "RGB"[c]), [&](std::size_t i) { return image.pixels[i][c]; });
  if (!aovs) return exr;
  if (aovs->normal.size() != n) throw std::runtime_error("exr_channels: the AOVs and the image differ in size");
  for (int c = 0; c < 3; ++c)
    add(std::string("normal.") + "XYZ"[c], [&](std::size_t i) { return aovs->normal[i][c]; });
  add("depth.Z", [&](std::size_t i) { return aovs->depth[i]; });
  for (int c = 0; c < 3; ++c)
    add(std::string("albedo.") + "RGB"[c], [&](std::size_t i) { return aovs->albedo[i][c]; });
  add("grain_id.id", [&](std::size_t i) { return aovs->label[i]; });
  return exr;
}

void write_exr(const std::filesystem::path& path, const ExrChannels& exr) {
  const shading::PixelWindow& d = exr.data;
  if (d.empty() || exr.channels.empty()) throw std::runtime_error("write_exr: empty image for " + path.string());
  std::ostringstream bytes;
  try {
    Imf::StdOSStream stream;
    Imf::Header header(Imath::Box2i({0, 0}, {exr.width - 1, exr.height - 1}),
                       Imath::Box2i({d.x0, d.y0}, {d.x1 - 1, d.y1 - 1}));
    for (const auto& [name, plane] : exr.channels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(stream, header);
    Imf::FrameBuffer frame;
    const std::size_t row = sizeof(float) * d.width();
    for (const auto& [name, plane] : exr.channels) {
      if (plane.size() != static_cast<std::size_t>(d.width()) * d.height())
        throw std::runtime_error("channel " + name + " does not fill the data window");
      // OpenEXR addresses pixel (x, y) at base + x·xStride + y·yStride, in the frame's coordinates.
      char* base = const_cast<char*>(reinterpret_cast<const char*>(plane.data())) - d.x0 * sizeof(float) - d.y0 * row;
      frame.insert(name, Imf::Slice(Imf::FLOAT, base, sizeof(float), row));
    }
    file.setFrameBuffer(frame);
    file.writePixels(d.height());
    bytes << stream.str();
  } catch (const std::exception& e) {
    throw std::runtime_error("write_exr: " + path.string() + ": " + e.what());
  }
  write_file_atomically(path, bytes.str());
}

void write_exr(const std::filesystem::path& path, const shading::Image& image) {
  if (image.width < 1 || image.height < 1) throw std::runtime_error("write_exr: empty image for " + path.string());
  write_exr(path, exr_channels(image));
}

ExrChannels read_exr_channels(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i display = file.header().displayWindow(), window = file.header().dataWindow();
    ExrChannels exr{display.max.x - display.min.x + 1, display.max.y - display.min.y + 1,
                    {window.min.x, window.min.y, window.max.x + 1, window.max.y + 1}, {}};
    const std::size_t row = sizeof(float) * exr.data.width();
    Imf::FrameBuffer frame;
    for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) {
      const std::size_t count = static_cast<std::size_t>(exr.data.width()) * exr.data.height();
      auto& plane = exr.channels.emplace_back(c.name(), std::vector<float>(count)).second;
      char* base = reinterpret_cast<char*>(plane.data()) - window.min.x * sizeof(float) - window.min.y * row;
      frame.insert(c.name(), Imf::Slice(Imf::FLOAT, base, sizeof(float), row, 1, 1, 0.0));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return exr;
  } catch (const std::exception& e) {
    throw std::runtime_error("read_exr: " + path.string() + ": " + e.what());
  }
}

const std::vector<float>& exr_channel(const ExrChannels& exr, const std::string& name) {
  for (const auto& [channel, plane] : exr.channels)
    if (channel == name) return plane;
  throw std::runtime_error("exr: no channel " + name);
}

shading::Image exr_beauty(const ExrChannels& exr) {
  shading::Image image(exr.data.width(), exr.data.height());
  for (int c = 0; c < 3; ++c) {
    const std::vector<float>& plane = exr_channel(exr, std::string(1, "RGB"[c]));
    for (std::size_t i = 0; i < plane.size(); ++i) image.pixels[i][c] = plane[i];
  }
  return image;
}

shading::Image read_exr(const std::filesystem::path& path) {
  const ExrChannels exr = read_exr_channels(path);
  try {
    return exr_beauty(exr);
  } catch (const std::exception& e) {
    throw std::runtime_error("read_exr: " + path.string() + ": " + e.what());
  }
}

}  // namespace rice::experiments
