// The box a render's default camera frames; see framing_box.hpp.
#include "experiments/render/framing_box.hpp"

#include <algorithm>

namespace rice::experiments {
namespace {

/// The k-th smallest of `values`, which it reorders.
double ranked(std::vector<double>& values, size_t k) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

Eigen::AlignedBox3d framing_box(const std::vector<Eigen::AlignedBox3d>& grains) {
  Eigen::AlignedBox3d kept;
  if (grains.empty()) return kept;
  double diagonal = 0.0;
  for (const auto& box : grains) diagonal = std::max(diagonal, box.diagonal().norm());
  Eigen::AlignedBox3d bulk;
  const size_t n = grains.size(), tail = (n - 1) / 100;  // the 1st and 99th percentiles' ranks
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> centres;
    for (const auto& box : grains) centres.push_back(box.center()[axis]);
    const double lo = ranked(centres, tail), hi = ranked(centres, n - 1 - tail);
    const double margin = 0.1 * (hi - lo) + diagonal;
    bulk.min()[axis] = lo - margin;
    bulk.max()[axis] = hi + margin;
  }
  for (const auto& box : grains)
    if (bulk.contains(box.center())) kept.extend(box);
  return kept;
}

}  // namespace rice::experiments
