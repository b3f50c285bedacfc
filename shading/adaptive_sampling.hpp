// Adaptive sampling, shared by the integrators (renderer.hpp, path_tracer.hpp): a pixel stops
// taking samples once its mean is known well enough. A pilot sets the target: every 8th pixel
// of the whole image, in each direction, takes `min_samples`, and τ = relative_error × their
// mean radiance (the whole image's, not a crop's, so that a crop renders the frame's very
// pixels). Each pixel then takes `min_samples`, and more in runs that double its count (so that
// a Sobol pixel stops at a power of two, where its points are a (0,2)-net), until the standard
// error of its mean, s/√n from the sample variance of its samples' channel means, is at most
// τ, or it reaches samples_per_pixel. Equal standard errors spend the samples where the noise
// is: a pixel of flat backdrop stops early, one in a soft shadow or between grains goes on.
//
// A pixel's samples are those of the same indices a fixed count would take, so a pixel that
// never stops early is the fixed render's pixel, bit for bit, and the image depends on the
// seed alone, not on the threads. Stopping on the samples' own variance leans slightly towards
// pixels whose rare bright paths have not shown yet; the render studies measure the error it
// leaves against the reference.
//
// Written by hand: nothing in reach (Embree, TBB) samples adaptively; the rule is the
// per-pixel variance stop of production renderers (Cycles' adaptive sampling stops on a
// half-buffer estimate of the same error).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "shading/image.hpp"
#include "shading/image_tiles.hpp"

namespace rice::shading {

struct AdaptiveSampling {
  double relative_error = 0.0;  ///< τ / the image's mean radiance; 0: off, every pixel takes samples_per_pixel
  int min_samples = 16;         ///< every pixel's first samples, and each pilot pixel's
  bool on() const { return relative_error > 0.0; }
};

/// Throws std::invalid_argument, naming `who`, for an error that is not in [0, 1) or, with
/// adaptive sampling on, a pilot of fewer than two samples (no variance to measure).
inline void validate(const AdaptiveSampling& adaptive, const std::string& who) {
  if (!(adaptive.relative_error >= 0.0 && adaptive.relative_error < 1.0) ||
      (adaptive.on() && adaptive.min_samples < 2))
    throw std::invalid_argument(who + ": adaptive sampling needs an error in [0, 1) and at least 2 samples first");
}

/// A pixel's running sums over its samples.
struct PixelSums {
  Eigen::Array3f sum = Eigen::Array3f::Zero();
  double value = 0.0, value_squared = 0.0;  ///< Σ v, Σ v² of the samples' channel means v
  int count = 0;

  void add(const Eigen::Array3f& c) {
    sum += c;
    const double v = (static_cast<double>(c[0]) + c[1] + c[2]) / 3.0;
    value += v;
    value_squared += v * v;
    ++count;
  }
  Eigen::Array3f mean() const { return count > 0 ? Eigen::Array3f(sum / static_cast<float>(count)) : sum; }
  /// s/√n: the standard error of the mean of v (infinite below two samples).
  double standard_error() const {
    if (count < 2) return std::numeric_limits<double>::infinity();
    const double n = count, variance = std::max(0.0, (value_squared - value * value / n) / (n - 1.0));
    return std::sqrt(variance / n);
  }
};

/// τ of the file comment: relative_error × the mean radiance of the pilot's pixels, every 8th
/// of the width × height image in each direction, sampled by `make_sampler()` (see
/// sample_pixels) in parallel and summed in order.
template <class MakeSampler>
double adaptive_target(int width, int height, const AdaptiveSampling& adaptive, MakeSampler&& make_sampler) {
  constexpr int kStride = 8;
  const int columns = (width + kStride - 1) / kStride, rows = (height + kStride - 1) / kStride;
  std::vector<double> means(static_cast<std::size_t>(columns) * rows);
  tbb::parallel_for(0, rows, [&](int j) {
    auto sampler = make_sampler();
    for (int i = 0; i < columns; ++i) {
      PixelSums sums;
      sampler(std::min(width - 1, kStride / 2 + kStride * i), std::min(height - 1, kStride / 2 + kStride * j), 0,
              adaptive.min_samples, sums);
      means[static_cast<std::size_t>(j) * columns + i] = sums.value / sums.count;
    }
    sampler.finish();
  });
  double sum = 0.0;
  for (const double m : means) sum += m;
  return adaptive.relative_error * sum / static_cast<double>(means.size());
}

/// Renders `window`'s pixels of a width × height image. `make_sampler()` is called once per
/// tile and returns a tile's sampler s: s(x, y, first, count, sums) adds the pixel's samples
/// first, …, first + count − 1 to `sums`; s.finish() is called when its tile is done. Each
/// pixel takes samples_per_pixel, or with adaptive sampling on as the file comment says.
template <class MakeSampler>
Image sample_pixels(int width, int height, const PixelWindow& window, int samples_per_pixel,
                    const AdaptiveSampling& adaptive, const std::function<void(int, int)>& progress,
                    const std::function<bool()>& cancelled, MakeSampler&& make_sampler) {
  const bool on = adaptive.on() && adaptive.min_samples < samples_per_pixel;
  const double target = on ? adaptive_target(width, height, adaptive, make_sampler) : 0.0;
  const int first_run = on ? adaptive.min_samples : samples_per_pixel;
  Image image(window.width(), window.height());
  for_each_tile(window, progress, cancelled, [&](int x0, int y0, int x1, int y1) {
    auto sampler = make_sampler();
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        PixelSums sums;
        sampler(x, y, 0, first_run, sums);
        while (sums.count < samples_per_pixel && sums.standard_error() > target)
          sampler(x, y, sums.count, std::min(samples_per_pixel, 2 * sums.count) - sums.count, sums);
        image.at(x - window.x0, y - window.y0) = sums.mean();
      }
    }
    sampler.finish();
  });
  return image;
}

}  // namespace rice::shading
