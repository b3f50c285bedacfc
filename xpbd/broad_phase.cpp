// Sort and sweep; see broad_phase.hpp.
#include "xpbd/broad_phase.hpp"

#include <algorithm>
#include <numeric>

namespace rice::xpbd {

std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Box>& boxes) {
  const int n = static_cast<int>(boxes.size());
  std::vector<std::pair<int, int>> pairs;
  if (n < 2) return pairs;
  // Sweep along the axis of largest variance of the centres: fewest false overlaps.
  Vec3 mean = Vec3::Zero(), square = Vec3::Zero();
  for (const Box& b : boxes) {
    const Vec3 c = 0.5 * (b.lower + b.upper);
    mean += c;
    square += c.cwiseProduct(c);
  }
  int axis;
  (square / n - (mean / n).cwiseProduct(mean / n)).maxCoeff(&axis);
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return boxes[a].lower[axis] < boxes[b].lower[axis] || (boxes[a].lower[axis] == boxes[b].lower[axis] && a < b);
  });
  for (int k = 0; k < n; ++k) {
    const Box& a = boxes[order[k]];
    for (int m = k + 1; m < n && boxes[order[m]].lower[axis] <= a.upper[axis]; ++m)
      if (a.overlaps(boxes[order[m]])) pairs.emplace_back(std::minmax(order[k], order[m]));
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace rice::xpbd
