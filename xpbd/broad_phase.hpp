// Broad phase: every pair of axis-aligned boxes that overlap, by sort and sweep along the axis
// on which the box centres spread most (Baraff 1992). O(n log n + overlaps along that axis);
// deterministic, since pairs come out sorted.
#pragma once

#include <utility>
#include <vector>

#include "xpbd/types.hpp"

namespace rice::xpbd {

struct Box {
  Vec3 lower, upper;
  bool overlaps(const Box& other) const {
    return (lower.array() <= other.upper.array()).all() && (other.lower.array() <= upper.array()).all();
  }
};

/// Pairs (i, j), i < j, of overlapping boxes, in increasing order.
std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Box>& boxes);

}  // namespace rice::xpbd
