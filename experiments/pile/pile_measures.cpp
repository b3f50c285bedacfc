// Footprint and clusters of a pile; see pile_measures.hpp.
#include "experiments/pile/pile_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "xpbd/penetration.hpp"

namespace rice::experiments {
namespace {

/// The least value under or at which `fraction` of the (non-empty) values lie.
double value_under_fraction(std::vector<double> values, double fraction) {
  std::sort(values.begin(), values.end());
  const auto k = static_cast<size_t>(std::ceil(fraction * static_cast<double>(values.size()))) - 1;
  return values[std::min(k, values.size() - 1)];
}

}  // namespace

double footprint_radius(const std::vector<xpbd::Vec3>& centres, double fraction) {
  if (centres.empty()) return 0.0;
  xpbd::Vec3 mean = xpbd::Vec3::Zero();
  for (const xpbd::Vec3& c : centres) mean += c;
  mean /= static_cast<double>(centres.size());
  std::vector<double> radii;
  for (const xpbd::Vec3& c : centres) radii.push_back((c - mean).head<2>().norm());
  return value_under_fraction(radii, fraction);
}

double pile_top(const std::vector<xpbd::Vec3>& centres, double fraction) {
  if (centres.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> heights;
  for (const xpbd::Vec3& c : centres) heights.push_back(c.z());
  return value_under_fraction(heights, fraction);
}

int count_clusters(const xpbd::Model& model, double gap) {
  // Body pairs whose sphere boxes, grown by the gap, overlap (the sort-and-sweep broad phase),
  // then their sphere pairs; touching pairs join their groups (union–find).
  const std::vector<xpbd::PlacedSpheres> placed = xpbd::placed_spheres(model);
  std::vector<xpbd::Box> boxes;
  for (const xpbd::PlacedSpheres& p : placed)
    boxes.push_back({p.box.lower - xpbd::Vec3::Constant(gap), p.box.upper});
  const auto touch = [&](int a, int b) {
    const xpbd::PlacedSpheres &pa = placed[a], &pb = placed[b];
    for (size_t i = 0; i < pa.centres.size(); ++i)
      for (size_t j = 0; j < pb.centres.size(); ++j)
        if ((pa.centres[i] - pb.centres[j]).norm() < pa.radii[i] + pb.radii[j] + gap) return true;
    return false;
  };
  std::vector<int> parent(placed.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int b) {
    while (parent[b] != b) b = parent[b] = parent[parent[b]];
    return b;
  };
  int groups = static_cast<int>(placed.size());
  for (const auto& [a, b] : xpbd::overlapping_pairs(boxes))
    if (root(a) != root(b) && touch(a, b)) {
      parent[root(a)] = root(b);
      --groups;
    }
  return groups;
}

}  // namespace rice::experiments
