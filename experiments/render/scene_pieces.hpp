// The pieces every rice render is made of (`rice render`, figure 13, the render and CDRF
// studies): the rice material and the grain's medium at a water content, a grain prototype with
// its vertex curvature, a ground, a sun's direction, and a camera that frames a box.
#pragma once

#include <Eigen/Geometry>

#include "shading/camera.hpp"
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

/// Adds `V, F` as a prototype with its jet-fitted vertex curvature and its thickness (for the
/// translucent model); returns its index.
int add_grain_prototype(shading::RenderScene& scene, const shading::MeshVertices& V, const shading::MeshTriangles& F);

/// Adds the rectangle [x0, x1] × [y0, y1] at height z, facing +z (a ground, a plate, a
/// cloth), as its own prototype and instance with `material`.
void add_ground(shading::RenderScene& scene, double x0, double y0, double x1, double y1, double z, int material);

/// The unit vector at the given elevation and azimuth (from +x towards +y) [degrees].
Eigen::Vector3d direction_from(double elevation_degrees, double azimuth_degrees);

}  // namespace rice::experiments
