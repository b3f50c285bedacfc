// Mean curvature of a triangle mesh at its vertices, for the CDRF's σ = σ0 κ (paper eq. 8).
//
// Method: at each vertex, CGAL's Monge_via_jet_fitting (Cazals & Pouget 2005) fits a
// polynomial height field z(x, y) of degree `jet_degree` by least squares to the vertex and
// its neighbours up to `rings` edges away, in the frame of their principal components, and
// reads the principal curvatures k1, k2 off its second-order coefficients (its Monge form).
// Measured on icospheres and a 7 × 3 × 2 mm ellipsoid (tests/shading/test_curvature.cpp):
// degree 2 (the default) is second order on the sphere, 0.8% at 2562 vertices, and 1.6% at
// the ellipsoid's tips at 10242, for 10 µs a vertex; degree 4 reaches 0.03% and 0.2% there
// for 60 µs a vertex, but overfits coarse meshes (33% at the tips with 642 vertices, against
// 8% for degree 2). The Monge normal is oriented along the mesh's area-weighted vertex normal, so
// H = (k1 + k2)/2 is positive where the surface bends away from its outward normal: a
// sphere of radius r gives +1/r, a dimple a negative value.
#pragma once

#include <Eigen/Dense>

namespace rice::shading {

/// #V by 3 vertex positions, one vertex a row (the Eigen layout every module shares).
using MeshVertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #F by 3 vertex indices, counter-clockwise seen from outside.
using MeshTriangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct CurvatureOptions {
  int jet_degree = 2;  ///< degree of the fitted height field (2–4); the Monge form is degree 2
  int rings = 2;       ///< neighbourhood; widened ring by ring where it holds too few points
};

/// Mean curvature H [1/length] at every vertex (#V). A vertex whose piece of surface holds
/// fewer vertices than the jet has coefficients (a fragment split off a porous surface) gets
/// 1/r of the sphere of its fragment's mean radius. Throws std::invalid_argument for
/// out-of-range indices, degrees outside 2–4 or rings < 1, and std::runtime_error naming a
/// vertex in no triangle.
Eigen::VectorXd vertex_mean_curvature(const MeshVertices& V, const MeshTriangles& F,
                                      const CurvatureOptions& options = {});

/// Area-weighted (unnormalised triangle normals summed) unit vertex normals, #V by 3.
MeshVertices vertex_normals(const MeshVertices& V, const MeshTriangles& F);

}  // namespace rice::shading
