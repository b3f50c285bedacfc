// What every integrator (renderer.hpp, path_tracer.hpp) shares around its pixels: the check
// of the instances' materials, and the image cut into tiles of kTileSize² pixels that run on
// TBB's threads, the unit of work, of progress and of cancelling. A tile's pixels depend only
// on the seed, so the image is the same on any thread count.
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

inline int tile_count(int width, int height) {
  return ((width + kTileSize - 1) / kTileSize) * ((height + kTileSize - 1) / kTileSize);
}

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

/// Calls `tile(x0, y0, x1, y1)` for each tile of a width × height image, its pixels
/// [x0, x1) × [y0, y1), in parallel; then `progress(done, total)` from the thread that
/// rendered it. Once `cancelled()` returns true no further tile starts.
template <class Tile>
void for_each_tile(int width, int height, const std::function<void(int, int)>& progress,
                   const std::function<bool()>& cancelled, Tile&& tile) {
  const int tiles_x = (width + kTileSize - 1) / kTileSize, tiles = tile_count(width, height);
  std::atomic<int> done = 0;
  tbb::parallel_for(0, tiles, [&](int k) {
    if (cancelled && cancelled()) return;
    const int x0 = (k % tiles_x) * kTileSize, y0 = (k / tiles_x) * kTileSize;
    tile(x0, y0, std::min(x0 + kTileSize, width), std::min(y0 + kTileSize, height));
    const int finished = ++done;
    if (progress) progress(finished, tiles);
  });
}

}  // namespace rice::shading
