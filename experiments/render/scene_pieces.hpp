// The pieces every rice render is made of (`rice render`, figure 13, the render and CDRF
// studies): the rice material and the grain's medium at a water content, a grain prototype with
// its shading (curvature, normals at the light's scale, thickness), a ground and a sun's
// direction.
#pragma once

#include <algorithm>

#include <Eigen/Geometry>

#include "shading/material.hpp"
#include "shading/random_walk.hpp"
#include "shading/render_scene.hpp"

namespace rice::experiments {

/// The rice material at water absorption W: CDRF σ0 and albedo from the water-content model,
/// and a wet, slightly rough dielectric surface.
shading::Material rice_material(double absorption_percent);

/// The grain's medium at water absorption W for the random-walk reference: the optics of the
/// water-content model, isotropic scattering with μs = μs' (the similarity relation).
shading::Medium grain_medium(double absorption_percent);

/// [m] The scales light averages a grain's surface over (shading/smooth_normals.hpp): the
/// shading normals over 1.2 mm, the curvature (the CDRF's σ = σ0 κ) over 0.4 mm, about two mean
/// free paths 1/μs′ at W 20% and twice the largest surface bump's radius. The bumps' specks go
/// and the silhouette stays. Measured against the random-walk reference per vertex (`rice study
/// translucency --shading-radius-mm --curvature-radius-mm`, docs/rendering.md): both models
/// gain from the wider normals; the CDRF loses when its curvature is averaged wider than 0.4 mm.
inline constexpr double kShadingRadius = 1.2e-3;
inline constexpr double kCurvatureRadius = 0.4e-3;

/// [m] The curvature's smoothing radius for shading normals smoothed over `shading_radius`.
inline double curvature_radius(double shading_radius) { return std::min(shading_radius, kCurvatureRadius); }

/// What a grain mesh is shaded with, per vertex: the normals smoothed over `shading_radius`,
/// the jet-fitted mean curvature over the smaller of it and kCurvatureRadius (0: the mesh's
/// own, both), and the thickness for the translucent model.
struct GrainShading {
  Eigen::VectorXd curvature, thickness;
  shading::MeshVertices normals;
};
GrainShading grain_shading(const shading::MeshVertices& V, const shading::MeshTriangles& F,
                           double shading_radius = kShadingRadius);

/// Adds `V, F` as a prototype shaded with `shading`; returns its index.
int add_grain_prototype(shading::RenderScene& scene, const shading::MeshVertices& V, const shading::MeshTriangles& F,
                        const GrainShading& shading,
                        shading::RenderScene::Reuse reuse = shading::RenderScene::Reuse::kShared);
/// The same with grain_shading(V, F, shading_radius).
int add_grain_prototype(shading::RenderScene& scene, const shading::MeshVertices& V, const shading::MeshTriangles& F,
                        double shading_radius = kShadingRadius);

/// Adds the rectangle [x0, x1] × [y0, y1] at height z, facing +z (a ground, a plate, a
/// cloth), as its own prototype and instance with `material`.
void add_ground(shading::RenderScene& scene, double x0, double y0, double x1, double y1, double z, int material);

/// The unit vector at the given elevation and azimuth (from +x towards +y) [degrees].
Eigen::Vector3d direction_from(double elevation_degrees, double azimuth_degrees);

}  // namespace rice::experiments
