// What every integrator (renderer.hpp, path_tracer.hpp) shares around its pixels: the check
// of the instances' materials, and the image cut into tiles of kTileSize² pixels that run on
// TBB's threads, the unit of work, of progress and of cancelling. A pixel depends only on the
// seed and its own coordinates, so the image is the same on any thread count, and a crop
// window renders the very pixels the whole frame has there: a frame split into crops and
// merged is the frame, byte for byte.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>

#include "shading/render_scene.hpp"

namespace rice::shading {

constexpr int kTileSize = 16;

/// The pixels [x0, x1) × [y0, y1) of an image: a crop window. The empty default stands for the
/// whole image.
struct PixelWindow {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

/// The pixels a render of a width × height image with `crop` covers; throws
/// std::invalid_argument, naming `who`, for a crop that is not empty and not inside the image.
inline PixelWindow rendered_pixels(int width, int height, const PixelWindow& crop, const std::string& who) {
  if (crop.empty()) return {0, 0, width, height};
  if (crop.x0 < 0 || crop.y0 < 0 || crop.x1 > width || crop.y1 > height)
    throw std::invalid_argument(who + ": the crop window [" + std::to_string(crop.x0) + ", " +
                                std::to_string(crop.x1) + ") x [" + std::to_string(crop.y0) + ", " +
                                std::to_string(crop.y1) + ") is not inside " + std::to_string(width) + " x " +
                                std::to_string(height));
  return crop;
}

inline int tile_count(int width, int height) {
  return ((width + kTileSize - 1) / kTileSize) * ((height + kTileSize - 1) / kTileSize);
}
inline int tile_count(const PixelWindow& window) { return tile_count(window.width(), window.height()); }

/// Throws std::invalid_argument, naming `who`, for no materials or an instance whose material
/// index is outside [0, material_count): checked once, rather than per hit.
inline void check_instance_materials(const RenderScene& scene, std::size_t material_count, const std::string& who) {
  if (material_count == 0) throw std::invalid_argument(who + ": no materials");
  for (int i = 0; i < scene.instance_count(); ++i) {
    const int m = scene.material_of(i);
    if (m < 0 || m >= static_cast<int>(material_count))
      throw std::invalid_argument(who + ": instance " + std::to_string(i) + " has material " + std::to_string(m) +
                                  " of " + std::to_string(material_count));
  }
}

/// Calls `tile(x0, y0, x1, y1)` for each tile of `window`, its pixels [x0, x1) × [y0, y1) in
/// the whole image's coordinates, in parallel; then `progress(done, total)` from the thread
/// that rendered it. Once `cancelled()` returns true no further tile starts.
template <class Tile>
void for_each_tile(const PixelWindow& window, const std::function<void(int, int)>& progress,
                   const std::function<bool()>& cancelled, Tile&& tile) {
  const int tiles_x = (window.width() + kTileSize - 1) / kTileSize, tiles = tile_count(window);
  std::atomic<int> done = 0;
  tbb::parallel_for(0, tiles, [&](int k) {
    if (cancelled && cancelled()) return;
    const int x0 = window.x0 + (k % tiles_x) * kTileSize, y0 = window.y0 + (k / tiles_x) * kTileSize;
    tile(x0, y0, std::min(x0 + kTileSize, window.x1), std::min(y0 + kTileSize, window.y1));
    const int finished = ++done;
    if (progress) progress(finished, tiles);
  });
}

}  // namespace rice::shading
