// Shading normals at the scale light averages over. A porous grain's render mesh carries
// bumps and dents a tenth of a millimetre across; light that enters the grain travels a mean
// free path or more (1/μs′, 0.1–1 mm) before it leaves, so its exitance follows the surface
// smoothed over that scale, not each bump. Shading with the mesh's own vertex normals lit the
// bumps' sun sides as bright specks and their far sides as dark pits (issue 24 §3); the
// random-walk reference shows neither.
//
// Method: each vertex's normal is the sum of the area-weighted vertex normals of the vertices
// within a ball of `radius` about it, weighted by a Gaussian of standard deviation radius/2
// in their distance, over those that face the same way (n_u · n_v > 0: the far wall of a thin
// part, or a pore's wall behind the surface, does not count), normalised. Neighbours are found
// in a uniform hash grid of cell `radius`. Written by hand: CGAL's normal estimation (PCA,
// jet fitting) fits point sets without the mesh's orientation and areas, which this needs.
#pragma once

#include "shading/curvature.hpp"

namespace rice::shading {

/// Unit smoothed normals, #V by 3; radius 0 returns vertex_normals(V, F). Throws
/// std::invalid_argument for a negative radius.
MeshVertices smoothed_vertex_normals(const MeshVertices& V, const MeshTriangles& F, double radius);

}  // namespace rice::shading
