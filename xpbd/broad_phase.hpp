// Broad phase: every pair of axis-aligned boxes that overlap. Few boxes: sort and sweep along
// the axis on which the box centres spread most (Baraff 1992), O(n log n + overlaps along
// that axis), which grows as n^(5/3) in a 3-d pile. Many: Embree's BVH-against-BVH collision
// (rtcCollide), O(n log n) to build and about O(n) to traverse. Deterministic: the pairs come
// out sorted, the same on any thread count.
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

/// From this many boxes, overlapping_pairs traverses Embree's BVH instead of sweeping
/// (bench_broad_phase, grain-sized boxes of a clump: the sweep 2.0 µs a box at 1000, 6.3 at
/// 10,000 and 12.3 at 34,000; the BVH 2.2, 2.4 and 2.8 µs, but 1.8 µs at 100 against 0.12).
constexpr int kBvhBroadPhaseFrom = 2000;

/// Pairs (i, j), i < j, of overlapping boxes (closed: touching faces overlap), in increasing order.
std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Box>& boxes);

/// The same, by sort and sweep alone, and by Embree's BVH alone (each exposed for the tests
/// and the benchmark).
std::vector<std::pair<int, int>> overlapping_pairs_by_sweep(const std::vector<Box>& boxes);
std::vector<std::pair<int, int>> overlapping_pairs_by_bvh(const std::vector<Box>& boxes);

}  // namespace rice::xpbd
