// Mesh to dense distance grid; see collider_grid.hpp.
#include "experiments/scene/collider_grid.hpp"

#include <cmath>
#include <stdexcept>

#include "grains/porous_level_set.hpp"

namespace rice::experiments {

xpbd::DistanceGrid distance_grid_of(const grains::SurfaceMesh& mesh, double spacing, double margin, bool hollow) {
  if (!(spacing > 0.0) || !std::isfinite(spacing) || !(margin >= 0.0))
    throw std::invalid_argument("distance grid: spacing must be positive and margin non-negative");
  constexpr double kBandVoxels = 3.0;
  const openvdb::FloatGrid::Ptr field = grains::signed_distance_field(mesh, spacing, kBandVoxels);
  // Grid points on OpenVDB's voxel centres: index ijk sits at ijk · spacing.
  const Eigen::Vector3d lower = mesh.V.colwise().minCoeff().transpose() - Eigen::Vector3d::Constant(margin);
  const Eigen::Vector3d upper = mesh.V.colwise().maxCoeff().transpose() + Eigen::Vector3d::Constant(margin);
  const Eigen::Vector3i first = (lower / spacing).array().floor().cast<int>();
  const Eigen::Vector3i last = (upper / spacing).array().ceil().cast<int>();
  xpbd::DistanceGrid grid;
  grid.spacing = spacing;
  grid.origin = first.cast<double>() * spacing;
  grid.size = last - first + Eigen::Vector3i::Ones();
  const double points = double(grid.size.x()) * grid.size.y() * grid.size.z();
  if (points > double(1 << 28))
    throw std::invalid_argument("distance grid: " + std::to_string(points) + " points; use a coarser spacing");
  grid.values.resize(static_cast<size_t>(points));
  const auto accessor = field->getConstAccessor();
  const float sign = hollow ? -1.0f : 1.0f;
  for (int k = 0; k < grid.size.z(); ++k)
    for (int j = 0; j < grid.size.y(); ++j)
      for (int i = 0; i < grid.size.x(); ++i)
        grid.values[i + grid.size.x() * (j + grid.size.y() * k)] =
            sign * accessor.getValue(openvdb::Coord(first.x() + i, first.y() + j, first.z() + k));
  return grid;
}

}  // namespace rice::experiments
