// Embedding of a high-resolution render mesh in a low-resolution simulation mesh (paper §4.3,
// after Müller & Chentanez's wrinkle meshes): each render vertex stores a tet of the
// simulation mesh and barycentric coordinates w (Σ w = 1); after the simulation moves the tet
// vertices x_0..x_3, the render vertex is Σ_k w_k x_k. Vertices outside the simulation mesh
// use the nearest tet, with coordinates extrapolated (some w_k < 0), so the map is affine per
// tet: exact at rest and rigid under rigid motion.
#pragma once

#include "grains/mesh_types.hpp"

namespace rice::grains {

struct Embedding {
  Eigen::VectorXi tet;  ///< #render vertices: tet index in the simulation mesh
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> weights;  ///< barycentric coordinates
};

/// Embeds `points` in `mesh`: the containing tet when there is one (largest smallest weight
/// among candidates), else the tet with the nearest boundary face.
Embedding embed_points(const Vertices& points, const VolumeMesh& mesh);

/// Render vertex i's position Σ_k w_k x_k for simulation positions `x` (#V by 3) and tets `T`.
inline Vec3 embedded_point(const Embedding& embedding, Eigen::Index i, const Vertices& x, const Tets& T) {
  const int t = embedding.tet[i];
  Vec3 p = Vec3::Zero();
  for (int k = 0; k < 4; ++k) p += embedding.weights(i, k) * x.row(T(t, k)).transpose();
  return p;
}

/// Render positions Σ_k w_k x_k for simulation positions `x` (#V by 3) and tets `T`.
Vertices apply_embedding(const Embedding& embedding, const Vertices& x, const Tets& T);

/// Render normals `N` (#V by 3, at the rest positions `X` of the simulation vertices) carried
/// to the simulation positions `x`: in tet t, the map is affine with deformation gradient
/// F = D_s D_m⁻¹ (D the edge matrices [x₁−x₀, x₂−x₀, x₃−x₀] deformed and at rest), and a normal
/// maps by the cofactor, n′ ∝ F⁻ᵀ n (Nanson's formula), normalised. Exact for normals that are
/// sums of area-weighted face normals (smoothed ones included) when the map is one affine map.
Vertices carry_normals(const Embedding& embedding, const Vertices& N, const Vertices& X, const Vertices& x,
                       const Tets& T);

/// Barycentric coordinates of p in tet (a, b, c, d) (any sign; the tet must not be flat).
Eigen::Vector4d barycentric_coordinates(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Distance from p to triangle (a, b, c).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace rice::grains
