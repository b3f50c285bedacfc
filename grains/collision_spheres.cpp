// Greedy sphere fitting; see collision_spheres.hpp.
#include "grains/collision_spheres.hpp"

#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

#include "grains/mesh_topology.hpp"
#include "grains/porous_level_set.hpp"
#include "grains/surface_measures.hpp"

namespace rice::grains {
namespace {

/// Points at barycentric coordinates (i, j, k)/3 of every boundary face: its corners, two
/// points on each edge and its centroid.
std::vector<Vec3> surface_samples(const SurfaceMesh& surface) {
  std::vector<Vec3> samples;
  for (Eigen::Index f = 0; f < surface.F.rows(); ++f) {
    const auto [a, b, c] = triangle_corners(surface, f);
    for (int i = 0; i <= 3; ++i)
      for (int j = 0; i + j <= 3; ++j) samples.push_back((i * a + j * b + (3 - i - j) * c) / 3.0);
  }
  return samples;
}

struct Candidate {
  Vec3 centre;
  double radius;
  std::vector<int> covers;  ///< samples within the tolerance of its surface
};

}  // namespace

void validate(const CollisionSphereParameters& p) {
  const auto check = [](bool ok, const char* name, const char* range) {
    if (!ok) throw std::invalid_argument(std::string("collision spheres: ") + name + " must be " + range);
  };
  check(p.tolerance > 0.0 && p.tolerance <= 0.5, "tolerance", "in (0, 0.5] (fraction of the thickness)");
  check(p.voxel_size > 0.0 && p.voxel_size <= 0.25, "voxel size", "in (0, 0.25] (fraction of the thickness)");
  check(p.max_spheres >= 1 && p.max_spheres <= 1000, "max spheres", "in [1, 1000]");
}

CollisionSpheres fit_collision_spheres(const VolumeMesh& mesh, const CollisionSphereParameters& parameters) {
  if (mesh.T.rows() == 0) throw std::invalid_argument("collision spheres: the mesh has no tets");
  return fit_collision_spheres(boundary_surface(mesh), parameters);
}

CollisionSpheres fit_collision_spheres(const SurfaceMesh& surface, const CollisionSphereParameters& parameters) {
  validate(parameters);
  if (surface.F.rows() == 0) throw std::invalid_argument("collision spheres: the surface has no faces");
  const double thickness = bounding_box_extent(surface.V).minCoeff();
  const double tolerance = parameters.tolerance * thickness;
  const double voxel = parameters.voxel_size * thickness;
  const std::vector<Vec3> samples = surface_samples(surface);

  // Candidates: interior voxels deeper than half a voxel, radius −φ.
  const openvdb::FloatGrid::Ptr field = signed_distance_field(surface, voxel, 3.0);
  std::vector<Candidate> candidates;
  for (auto it = field->cbeginValueOn(); it; ++it) {
    if (!it.isVoxelValue() || !(*it < -0.5 * voxel)) continue;
    const openvdb::Vec3d p = field->indexToWorld(it.getCoord());
    Candidate candidate{Vec3(p.x(), p.y(), p.z()), -double(*it), {}};
    for (int s = 0; s < static_cast<int>(samples.size()); ++s)
      if ((samples[s] - candidate.centre).norm() - candidate.radius <= tolerance) candidate.covers.push_back(s);
    if (!candidate.covers.empty()) candidates.push_back(std::move(candidate));
  }
  if (candidates.empty()) throw std::invalid_argument("collision spheres: the mesh has no interior deeper than half a voxel");
  // Deterministic order whatever the grid's iteration order.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return std::lexicographical_compare(x.centre.data(), x.centre.data() + 3, y.centre.data(), y.centre.data() + 3);
  });

  // Lazy greedy set cover: a candidate's count of uncovered samples only falls, so a popped
  // candidate whose recounted value still beats the next one is the best.
  std::vector<bool> covered(samples.size(), false);
  const auto uncovered_count = [&](int c) {
    int n = 0;
    for (const int s : candidates[c].covers) n += !covered[s];
    return n;
  };
  std::priority_queue<std::pair<int, int>> queue;  // (count, −index): ties go to the lowest index
  for (int c = 0; c < static_cast<int>(candidates.size()); ++c) queue.emplace(uncovered_count(c), -c);
  CollisionSpheres result;
  std::vector<int> chosen;
  int left = static_cast<int>(samples.size());
  while (left > 0 && static_cast<int>(chosen.size()) < parameters.max_spheres && !queue.empty()) {
    const auto [count, negative_index] = queue.top();
    queue.pop();
    const int c = -negative_index;
    const int now = uncovered_count(c);
    if (now == 0) continue;
    if (!queue.empty() && now < queue.top().first) {
      queue.emplace(now, negative_index);
      continue;
    }
    chosen.push_back(c);
    for (const int s : candidates[c].covers) left -= !covered[s], covered[s] = true;
  }
  result.centres.resize(chosen.size(), 3);
  result.radii.resize(chosen.size());
  for (size_t k = 0; k < chosen.size(); ++k) {
    result.centres.row(k) = candidates[chosen[k]].centre.transpose();
    result.radii[k] = candidates[chosen[k]].radius;
  }
  result.uncovered_samples = left;
  for (const Vec3& sample : samples) {
    double gap = INFINITY;
    for (size_t k = 0; k < chosen.size(); ++k)
      gap = std::min(gap, (sample - result.centres.row(k).transpose()).norm() - result.radii[k]);
    result.max_gap = std::max(result.max_gap, gap);
  }
  return result;
}

}  // namespace rice::grains
