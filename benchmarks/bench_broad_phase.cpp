// Google Benchmark of the broad phase (xpbd/broad_phase.hpp) on a clump of grain-sized boxes,
// as `rice study scale` drops them: n boxes of 7 x 3.5 x 2.5 mm, turned at random, in a cube
// whose side grows as n^(1/3) (20 mm for 100). Argument: n. Counter `ns/box`: time per box,
// flat for an O(n) broad phase. Compared: sort and sweep, Embree's BVH collision, and CGAL's
// box_self_intersection_d (Zomorodian and Edelsbrunner's streamed segment tree; measured and
// not used: 2.0 us a box at 1000, 4.2 us at 34,000, still growing).
#include <benchmark/benchmark.h>

#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "xpbd/broad_phase.hpp"

namespace {

using namespace rice::xpbd;
using Pairs = std::vector<std::pair<int, int>>;

std::vector<Box> clump(int n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double side = 0.02 * std::cbrt(n / 100.0);
  const Vec3 half(3.5e-3, 1.75e-3, 1.25e-3);
  std::vector<Box> boxes(n);
  for (Box& b : boxes) {
    const Eigen::Quaterniond q(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
    const Vec3 extent = q.normalized().toRotationMatrix().cwiseAbs() * half;
    const Vec3 centre(side * unit(rng), side * unit(rng), side * unit(rng));
    b = {centre - extent, centre + extent};
  }
  return boxes;
}

Pairs cgal_pairs(const std::vector<Box>& boxes) {
  using CBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int, CGAL::Box_intersection_d::ID_EXPLICIT>;
  std::vector<CBox> c;
  c.reserve(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    double lo[3] = {boxes[i].lower.x(), boxes[i].lower.y(), boxes[i].lower.z()};
    double hi[3] = {boxes[i].upper.x(), boxes[i].upper.y(), boxes[i].upper.z()};
    c.emplace_back(lo, hi, static_cast<int>(i));
  }
  Pairs pairs;
  CGAL::box_self_intersection_d<CGAL::Parallel_if_available_tag>(
      c.begin(), c.end(), [&](const CBox& a, const CBox& b) { pairs.emplace_back(std::minmax(a.info(), b.info())); },
      std::ptrdiff_t(10), CGAL::Box_intersection_d::CLOSED);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

template <Pairs (*Find)(const std::vector<Box>&)>
void BM_BroadPhase(benchmark::State& state) {
  const std::vector<Box> boxes = clump(static_cast<int>(state.range(0)));
  if (Find(boxes) != overlapping_pairs_by_sweep(boxes)) state.SkipWithError("pairs differ from the sweep's");
  size_t pairs = 0;
  for (auto _ : state) pairs = Find(boxes).size();
  state.counters["pairs/box"] = static_cast<double>(pairs) / boxes.size();
  state.counters["ns/box"] = benchmark::Counter(
      static_cast<double>(boxes.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
void counts(benchmark::internal::Benchmark* b) {
  for (const int n : {100, 1000, 3000, 10000, 34000}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_BroadPhase<overlapping_pairs_by_sweep>)->Apply(counts);
BENCHMARK(BM_BroadPhase<overlapping_pairs_by_bvh>)->Apply(counts);
BENCHMARK(BM_BroadPhase<cgal_pairs>)->Apply(counts);

}  // namespace

BENCHMARK_MAIN();
