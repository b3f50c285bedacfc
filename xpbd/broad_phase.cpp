// Sort and sweep, and Embree's BVH collision; see broad_phase.hpp.
#include "xpbd/broad_phase.hpp"

#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace rice::xpbd {
namespace {

/// The boxes and, per thread, the overlapping pairs rtcCollide's callback found.
struct BvhQuery {
  const std::vector<Box>& boxes;
  tbb::enumerable_thread_specific<std::vector<std::pair<int, int>>> found;
};

/// Single-precision bounds that hold the double box: rounded outwards, so that no overlap of
/// the doubles is lost; the callback then tests the doubles.
float round_down(double x) {
  const float f = static_cast<float>(x);
  return f > x ? std::nextafter(f, -INFINITY) : f;
}
float round_up(double x) {
  const float f = static_cast<float>(x);
  return f < x ? std::nextafter(f, INFINITY) : f;
}

void box_bounds(const RTCBoundsFunctionArguments* args) {
  const Box& b = static_cast<const BvhQuery*>(args->geometryUserPtr)->boxes[args->primID];
  *args->bounds_o = {round_down(b.lower.x()), round_down(b.lower.y()), round_down(b.lower.z()), 0.0f,
                     round_up(b.upper.x()),   round_up(b.upper.y()),   round_up(b.upper.z()),   0.0f};
}

void collect_pairs(void* user, RTCCollision* collisions, unsigned int count) {
  auto& query = *static_cast<BvhQuery*>(user);
  auto& found = query.found.local();
  for (unsigned int k = 0; k < count; ++k) {
    const int a = static_cast<int>(collisions[k].primID0), b = static_cast<int>(collisions[k].primID1);
    // A scene collided with itself reports each pair both ways, (a, b) and (b, a); one is kept.
    if (a < b && query.boxes[a].overlaps(query.boxes[b])) found.emplace_back(a, b);
  }
}

/// One Embree device for the process: making one costs more than a broad phase.
RTCDevice bvh_device() {
  static const RTCDevice device = [] {
    RTCDevice d = rtcNewDevice(nullptr);
    if (!d) throw std::runtime_error("broad phase: Embree device: error " + std::to_string(rtcGetDeviceError(nullptr)));
    return d;
  }();
  return device;
}

}  // namespace

std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Box>& boxes) {
  return static_cast<int>(boxes.size()) < kBvhBroadPhaseFrom ? overlapping_pairs_by_sweep(boxes)
                                                              : overlapping_pairs_by_bvh(boxes);
}

std::vector<std::pair<int, int>> overlapping_pairs_by_sweep(const std::vector<Box>& boxes) {
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

std::vector<std::pair<int, int>> overlapping_pairs_by_bvh(const std::vector<Box>& boxes) {
  BvhQuery query{boxes, {}};
  RTCScene scene = rtcNewScene(bvh_device());
  RTCGeometry geometry = rtcNewGeometry(bvh_device(), RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned int>(boxes.size()));
  rtcSetGeometryUserData(geometry, &query);
  rtcSetGeometryBoundsFunction(geometry, box_bounds, nullptr);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  rtcCollide(scene, scene, collect_pairs, &query);
  rtcReleaseScene(scene);
  std::vector<std::pair<int, int>> pairs;
  for (const auto& part : query.found) pairs.insert(pairs.end(), part.begin(), part.end());
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace rice::xpbd
