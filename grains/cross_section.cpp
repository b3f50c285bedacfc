// Trilinear samples of a level set on a z-plane (see cross_section.hpp).
#include "grains/cross_section.hpp"

#include <openvdb/tools/Interpolation.h>

#include <cmath>
#include <stdexcept>

namespace rice::grains {

Eigen::MatrixXf cross_section_z(const openvdb::FloatGrid& grid, const Vec3& low, const Vec3& high, double z,
                                double pixel) {
  if (!(pixel > 0.0)) throw std::invalid_argument("cross section: pixel size must be positive");
  const int columns = std::max(1, static_cast<int>(std::ceil((high.x() - low.x()) / pixel)));
  const int rows = std::max(1, static_cast<int>(std::ceil((high.y() - low.y()) / pixel)));
  openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(grid);
  Eigen::MatrixXf image(rows, columns);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j)
      image(i, j) = sampler.wsSample(
          openvdb::Vec3R(low.x() + (j + 0.5) * pixel, high.y() - (i + 0.5) * pixel, z));
  return image;
}

}  // namespace rice::grains
