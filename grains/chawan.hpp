// A procedural chawan (rice bowl) for the pour scenes: a closed surface of revolution about z
// with a solid foot, an outer wall and an inner wall that are half-ellipses about the rim's
// centre, and a flat rim. Default size: 12 cm across at the rim, 6.5 cm tall, 5.5 cm deep
// inside, walls about 4 mm thick (a typical chawan is 11–13 cm across and 6–7 cm tall).
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::grains {

struct ChawanShape {
  double rim_radius = 0.06;      ///< outer radius at the rim [m]
  double height = 0.065;         ///< foot to rim [m]
  double inner_depth = 0.055;    ///< rim to the inside bottom [m]
  double wall_thickness = 0.004; ///< at the rim [m]
  double foot_radius = 0.027;    ///< [m]
  double foot_height = 0.006;    ///< [m]
  int wall_points = 24;          ///< profile points along each wall
  int segments = 64;             ///< points around the axis
};

/// Throws std::invalid_argument naming the field when the walls would cross or a size is not
/// positive.
void validate(const ChawanShape& shape);

/// The same bowl `factor` times as large (its sizes scaled, its point counts kept).
ChawanShape scaled(const ChawanShape& shape, double factor);

/// The bowl's closed, manifold, outward-oriented surface, foot at z = 0, axis along z.
SurfaceMesh make_chawan(const ChawanShape& shape = {});

}  // namespace rice::grains
