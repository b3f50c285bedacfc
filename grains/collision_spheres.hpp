// Collision spheres of a grain: a small set of spheres inside its simulation mesh whose union
// follows the grain's surface to within a tolerance, the contact shape of xpbd/body.hpp.
// Fitted greedily: candidate centres are the interior voxels of the mesh's signed distance
// field (OpenVDB), each with the largest inscribed radius −φ; surface samples are the boundary
// vertices, edge midpoints and face centroids; a sphere covers a sample within `tolerance` of
// its surface, and the candidate covering most uncovered samples is taken until all are
// covered (greedy set cover; the medial-axis sphere sets of Bradshaw & O'Sullivan 2004 work
// the same way).
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::grains {

/// Defaults measured on three grains of each cultivar: 12–21 spheres for japonica and
/// glutinous, 21–39 for indica, 47–63 for slender aromatic grains, 0.05–0.2 s each. A tighter
/// tolerance (0.08) needed over 48 spheres for indica; sharp tips need candidates down to half
/// a voxel (0.04 T) deep.
struct CollisionSphereParameters {
  double tolerance = 0.12;   ///< largest gap between the surface and the spheres, fraction of thickness T
  double voxel_size = 0.04;  ///< distance-field voxel, fraction of T
  int max_spheres = 64;
};

struct CollisionSpheres {
  Vertices centres;       ///< #S by 3, grain frame [m]
  Eigen::VectorXd radii;  ///< #S [m]
  /// Largest distance from a surface sample to the union's surface [m]; the fit meets the
  /// tolerance when every sample was covered.
  double max_gap = 0.0;
  int uncovered_samples = 0;  ///< samples left when max_spheres ran out
};

/// Throws std::invalid_argument naming the parameter and its accepted range.
void validate(const CollisionSphereParameters& parameters);

/// Spheres for the tet mesh `mesh` (its boundary is the surface to follow). Deterministic.
CollisionSpheres fit_collision_spheres(const VolumeMesh& mesh, const CollisionSphereParameters& parameters = {});
/// Spheres for the closed surface `surface`. Deterministic.
CollisionSpheres fit_collision_spheres(const SurfaceMesh& surface, const CollisionSphereParameters& parameters = {});

}  // namespace rice::grains
