// Lattice of grain boxes inside a mould; see mould_fill.hpp.
#include "experiments/scene/mould_fill.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rice::experiments {

using xpbd::Vec3;

std::vector<Vec3> mould_lattice(const xpbd::Collider& mould, const Vec3& cell, const Vec3& shift) {
  if (mould.shape != xpbd::ColliderShape::kDistanceGrid || !mould.grid)
    throw std::invalid_argument("fill: the mould must be a mesh collider");
  if (!(cell.minCoeff() > 0.0) || !cell.allFinite()) throw std::invalid_argument("fill: the cell must be positive");
  if (!(shift.minCoeff() >= 0.0 && shift.maxCoeff() < 1.0))
    throw std::invalid_argument("fill: the lattice's shift must lie in [0, 1) cells");
  const xpbd::ColliderKeyframe pose = xpbd::collider_pose(mould, 0.0);
  const auto room = [&](const Vec3& world) {
    return xpbd::posed_signed_distance(mould, pose, xpbd::to_local(pose, world)).distance;
  };
  // The grid's box in the world.
  const xpbd::DistanceGrid& grid = *mould.grid;
  const Vec3 extent = grid.spacing * (grid.size - Eigen::Vector3i::Ones()).cast<double>();
  Vec3 lower = Vec3::Constant(INFINITY), upper = Vec3::Constant(-INFINITY);
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 local = grid.origin + Vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1).cwiseProduct(extent);
    const Vec3 world = xpbd::to_world(pose, local);
    lower = lower.cwiseMin(world);
    upper = upper.cwiseMax(world);
  }
  // A shift takes no box further past the grid's box than the odd layers' half cell does.
  const Eigen::Vector3i cells = ((upper - lower).cwiseQuotient(cell) - shift).array().floor().cast<int>();
  std::vector<Vec3> inside;
  for (int k = 0; k < cells.z(); ++k)
    for (int j = 0; j < cells.y(); ++j)
      for (int i = 0; i < cells.x(); ++i) {
        // Odd layers shifted by half a cell in x and y: each grain lands across four below.
        const double brick = (k % 2) ? 0.5 : 0.0;
        const Vec3 centre = lower + (Vec3(i + brick, j + brick, k) + shift + Vec3::Constant(0.5)).cwiseProduct(cell);
        bool fits = room(centre) > 0.5 * cell.minCoeff();
        for (int corner = 0; fits && corner < 8; ++corner)
          fits = room(centre + 0.5 * Vec3((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1)
                                           .cwiseProduct(cell)) > 0.0;
        if (fits) inside.push_back(centre);
      }
  return inside;
}

std::vector<Vec3> free_points(const std::vector<Vec3>& lattice, const std::vector<Vec3>& occupied, double clearance) {
  std::vector<Vec3> free;
  for (const Vec3& p : lattice)
    if (std::none_of(occupied.begin(), occupied.end(), [&](const Vec3& c) { return (c - p).norm() <= clearance; }))
      free.push_back(p);
  return free;
}

}  // namespace rice::experiments
