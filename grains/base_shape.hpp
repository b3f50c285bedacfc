// Parametric base model of a grain (paper §4.1, Fig. 5): a closed surface in the grain's
// frame — length along x, width along y, thickness along z, centred at the origin — with
// blunt tips, a wider dorsal side and the embryo notch. The surface is
//   x = (L/2) u,  y = (W/2) (1 ± a) s(u) cos φ,  z = (T/2) s(u) sin φ,
//   s(u) = (1 − |u|^p)^(1/p),  u = cos θ,  θ ∈ [0, π], φ ∈ [0, 2π),
// (+a where cos φ > 0), then the notch pulls points near (u, φ) = (0.8, π) towards the
// origin by d·exp(−|Δ|²/(2 r²)), with Δ the distance to the notch centre on the surface
// before the notch. The surface is star-shaped about the origin, so it never self-intersects.
#pragma once

#include "grains/cultivar.hpp"
#include "grains/mesh_types.hpp"

namespace rice::grains {

/// Tessellation of the base model: `rings` latitude bands from tip to tip and `segments`
/// vertices around each ring; two pole vertices at the tips.
struct BaseShapeResolution {
  int rings = 24;
  int segments = 24;
};

/// The closed, manifold, outward-oriented base surface of `shape` (swell factor not applied).
SurfaceMesh make_base_shape(const GrainShape& shape, const BaseShapeResolution& resolution = {});

}  // namespace rice::grains
