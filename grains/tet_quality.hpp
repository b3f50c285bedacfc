// Quality figures of tetrahedral meshes: signed volumes, dihedral angles, radius–edge ratios
// (circumradius over shortest edge; 0.61 for the regular tetrahedron, large for slivers and
// needles).
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::grains {

struct TetQuality {
  double min_volume = 0.0;             ///< smallest signed volume [m³]
  double min_dihedral_degrees = 0.0;   ///< over all tets and their six edges
  double max_dihedral_degrees = 0.0;
  double max_radius_edge_ratio = 0.0;  ///< circumradius / shortest edge
  double mean_radius_edge_ratio = 0.0;
};

/// Signed volume of tet (a, b, c, d): (b − a)·((c − a)×(d − a)) / 6.
double tet_signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Sum of the signed volumes of the tets of `mesh` [m³].
double total_volume(const VolumeMesh& mesh);

/// Quality of every tet of `mesh`, summarised.
TetQuality measure_tet_quality(const VolumeMesh& mesh);

}  // namespace rice::grains
