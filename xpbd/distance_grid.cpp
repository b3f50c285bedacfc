// Trilinear reading of a sampled signed distance field; see distance_grid.hpp.
#include "xpbd/distance_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rice::xpbd {

GridSample sample(const DistanceGrid& grid, const Vec3& p) {
  // Clamp into the grid; the part of p outside it adds its length to φ.
  const Vec3 upper = grid.origin + grid.spacing * (grid.size.cast<double>() - Vec3::Ones());
  const Vec3 inside = p.cwiseMax(grid.origin).cwiseMin(upper);
  const double outside = (p - inside).norm();
  const Vec3 u = (inside - grid.origin) / grid.spacing;
  int cell[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::min(static_cast<int>(std::floor(u[a])), grid.size[a] - 2);
    t[a] = u[a] - cell[a];
  }
  // φ = Σ corners w(i) w(j) w(k) φ_ijk with w = t or 1 − t; ∂φ/∂t_a by the same sum.
  double phi = 0.0;
  Vec3 d = Vec3::Zero();
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di) {
        const double value = grid.at(cell[0] + di, cell[1] + dj, cell[2] + dk);
        const double wx = di ? t[0] : 1.0 - t[0], wy = dj ? t[1] : 1.0 - t[1], wz = dk ? t[2] : 1.0 - t[2];
        phi += wx * wy * wz * value;
        d.x() += (di ? 1.0 : -1.0) * wy * wz * value;
        d.y() += (dj ? 1.0 : -1.0) * wx * wz * value;
        d.z() += (dk ? 1.0 : -1.0) * wx * wy * value;
      }
  Vec3 gradient = d / grid.spacing;
  if (outside > 0.0) gradient = (p - inside) / outside;  // away from the grid
  const double length = gradient.norm();
  return {phi + outside, length > 0.0 ? Vec3(gradient / length) : Vec3::UnitZ()};
}

void validate(const DistanceGrid& grid) {
  if (!(grid.spacing > 0.0) || !std::isfinite(grid.spacing) || !grid.origin.allFinite())
    throw std::invalid_argument("distance grid: needs a finite origin and a positive finite spacing");
  if ((grid.size.array() < 2).any())
    throw std::invalid_argument("distance grid: needs at least two points along each axis");
  const long count = static_cast<long>(grid.size.x()) * grid.size.y() * grid.size.z();
  if (static_cast<long>(grid.values.size()) != count)
    throw std::invalid_argument("distance grid: has " + std::to_string(grid.values.size()) + " values for " +
                                std::to_string(count) + " points");
  for (const float v : grid.values)
    if (!std::isfinite(v)) throw std::invalid_argument("distance grid: has a non-finite value");
}

}  // namespace rice::xpbd
