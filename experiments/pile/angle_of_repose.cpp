// Angle of repose of a heap; see angle_of_repose.hpp.
#include "experiments/pile/angle_of_repose.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rice::experiments {

HeapProfile heap_profile(const std::vector<xpbd::Vec3>& centres, double ring_width) {
  if (!(ring_width > 0.0)) throw std::invalid_argument("heap profile: the ring width must be > 0");
  if (centres.empty()) throw std::invalid_argument("heap profile: no grains");
  // The axis through the median x and y: grains that rolled far away do not move it.
  std::vector<double> xs, ys;
  double lowest = INFINITY;
  for (const xpbd::Vec3& c : centres) {
    xs.push_back(c.x());
    ys.push_back(c.y());
    lowest = std::min(lowest, c.z());
  }
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  std::nth_element(ys.begin(), ys.begin() + ys.size() / 2, ys.end());
  const xpbd::Vec3 axis(xs[xs.size() / 2], ys[ys.size() / 2], 0.0);
  // The highest centre of each ring.
  std::vector<double> radius, height;
  for (const xpbd::Vec3& c : centres) {
    const double r = std::hypot(c.x() - axis.x(), c.y() - axis.y());
    const size_t ring = static_cast<size_t>(r / ring_width);
    if (ring >= height.size()) {
      height.resize(ring + 1, -INFINITY);
      radius.resize(ring + 1, 0.0);
    }
    if (c.z() - lowest > height[ring]) {
      height[ring] = c.z() - lowest;
      radius[ring] = r;
    }
  }
  HeapProfile heap;
  heap.apex_height = *std::max_element(height.begin(), height.end());
  // Least squares over the flank's rings: height = intercept + slope · radius.
  double n = 0.0, sr = 0.0, sh = 0.0, srr = 0.0, srh = 0.0;
  for (size_t k = 0; k < height.size(); ++k) {
    if (!std::isfinite(height[k])) continue;  // an empty ring
    const bool flank = height[k] >= 0.15 * heap.apex_height && height[k] <= 0.85 * heap.apex_height;
    heap.ring_radius.push_back(radius[k]);
    heap.ring_height.push_back(height[k]);
    heap.on_flank.push_back(flank);
    if (!flank) continue;
    n += 1.0;
    sr += radius[k];
    sh += height[k];
    srr += radius[k] * radius[k];
    srh += radius[k] * height[k];
  }
  const double denominator = n * srr - sr * sr;
  if (n < 2.0 || !(denominator > 0.0))
    throw std::invalid_argument("heap profile: fewer than two rings on the heap's flank (too few grains?)");
  heap.slope = (n * srh - sr * sh) / denominator;
  heap.intercept = (sh - heap.slope * sr) / n;
  heap.angle_degrees = std::atan(-heap.slope) * 180.0 / M_PI;
  return heap;
}

}  // namespace rice::experiments
