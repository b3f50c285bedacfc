// Footprint and clusters of a pile; see pile_measures.hpp.
#include "experiments/pile_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "xpbd/body.hpp"

namespace rice::experiments {

double footprint_radius(const std::vector<xpbd::Vec3>& centres, double fraction) {
  if (centres.empty()) return 0.0;
  xpbd::Vec3 mean = xpbd::Vec3::Zero();
  for (const xpbd::Vec3& c : centres) mean += c;
  mean /= static_cast<double>(centres.size());
  std::vector<double> radii;
  for (const xpbd::Vec3& c : centres) radii.push_back((c - mean).head<2>().norm());
  std::sort(radii.begin(), radii.end());
  const auto k = static_cast<size_t>(std::ceil(fraction * static_cast<double>(radii.size()))) - 1;
  return radii[std::min(k, radii.size() - 1)];
}

int count_clusters(const xpbd::Model& model, double gap) {
  const int n = static_cast<int>(model.bodies.size());
  // Each body's spheres now, and their box grown by the gap.
  std::vector<std::vector<xpbd::Vec3>> centres(n);
  std::vector<std::vector<double>> radii(n);
  std::vector<xpbd::Vec3> lower(n, xpbd::Vec3::Constant(INFINITY)), upper(n, xpbd::Vec3::Constant(-INFINITY));
  for (int b = 0; b < n; ++b) {
    const xpbd::Body& body = model.bodies[b];
    for (int s = 0; s < body.sphere_count(); ++s) {
      centres[b].push_back(xpbd::sphere_centre(model, body, s));
      radii[b].push_back(xpbd::sphere_radius(model, body, s));
      lower[b] = lower[b].cwiseMin(centres[b].back() - xpbd::Vec3::Constant(radii[b].back() + gap));
      upper[b] = upper[b].cwiseMax(centres[b].back() + xpbd::Vec3::Constant(radii[b].back()));
    }
  }
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int b) {
    while (parent[b] != b) b = parent[b] = parent[parent[b]];
    return b;
  };
  const auto touch = [&](int a, int b) {
    if ((lower[a].array() > upper[b].array()).any() || (lower[b].array() > upper[a].array()).any()) return false;
    for (size_t i = 0; i < centres[a].size(); ++i)
      for (size_t j = 0; j < centres[b].size(); ++j)
        if ((centres[a][i] - centres[b][j]).norm() < radii[a][i] + radii[b][j] + gap) return true;
    return false;
  };
  int groups = n;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if (root(a) != root(b) && touch(a, b)) {
        parent[root(a)] = root(b);
        --groups;
      }
  return groups;
}

}  // namespace rice::experiments
