// Shading normals and curvature at the scale light averages over. A porous grain's render
// mesh carries bumps and dents a tenth of a millimetre across; light that enters the grain
// travels a mean free path or more (1/μs′, 0.1–1 mm) before it leaves, so its exitance
// follows the surface smoothed over that scale, not each bump. Shading with the mesh's own
// vertex normals and curvature lit the bumps' sun sides as bright specks and their far sides
// as dark pits (issue 24 §3); the random-walk reference shows neither.
//
// Method: each vertex's normal is the sum of the area-weighted vertex normals of the vertices
// within a ball of `radius` about it, weighted by a Gaussian of standard deviation radius/2
// in their distance, over those that face the same way (n_u · n_v > 0: the far wall of a thin
// part, or a pore's wall behind the surface, does not count), normalised. A vertex value (the
// mean curvature for the CDRF's σ) is averaged with the same weights times each vertex's
// area: for a surface of small slope H = ½ Δh is linear in the height h, so the smoothed H is
// the curvature of the smoothed surface. Neighbours are found in a uniform hash grid of cell
// `radius`. Written by hand: CGAL's normal estimation (PCA, jet fitting) fits point sets
// without the mesh's orientation and areas, which this needs.
#pragma once

#include "shading/curvature.hpp"

namespace rice::shading {

/// Unit smoothed normals, #V by 3; radius 0 returns vertex_normals(V, F). Throws
/// std::invalid_argument for a negative radius.
MeshVertices smoothed_vertex_normals(const MeshVertices& V, const MeshTriangles& F, double radius);

/// `values` (#V) averaged over the same ball, area-weighted; radius 0 returns them. Throws
/// std::invalid_argument for a negative radius or a wrong count.
Eigen::VectorXd smoothed_vertex_values(const MeshVertices& V, const MeshTriangles& F, const Eigen::VectorXd& values,
                                       double radius);

}  // namespace rice::shading
