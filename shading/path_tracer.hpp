// The reference integrator: unidirectional path tracing that follows light through everything
// the scene holds, the ground truth for a given set of optics (the fast models are measured
// against it; issue 24, part 1).
//
// A path starts at the camera. At a rice grain (a material with a medium) it meets a smooth
// dielectric boundary of relative index η: it reflects with the Fresnel reflectance F(θ) and
// otherwise refracts in (Snell). Inside it random-walks as random_walk.hpp does (exponential
// free paths in σ_t = σ_s + σ_a, Henyey–Greenstein scattering, weight σ_s/σ_t a scattering),
// meeting only its own grain's surface (RenderScene::intersect_instance), where Fresnel again
// decides between internal reflection and leaving. Out of the grain it goes on to other
// grains, the bowl, the ground and the sky. At other surfaces (diffuse, glazed and a rice
// material without a medium are taken as Lambertian of their albedo) it gathers the suns and
// quad lights by shadow rays and bounces in a cosine-weighted direction; a metal gathers them
// through its GGX lobe and bounces into that lobe. With a CDRF table
// in the settings, a rice material without a medium is instead the fast model of
// material.hpp: the CDRF and its translucency, lit by shadow rays that see through the grain
// itself, bouncing into its response, front and back; paths of max_depth 1, 2, 3 are that
// model with 0, 1, 2 bounces of light between grains (`rice study render`).
//
// What light reaches a path:
//  - the environment, whenever the path leaves the scene;
//  - a sun, through a shadow ray from a diffuse surface; off a grain's surface, through the
//    material's GGX lobe and a shadow ray (`rough_sun_glints`: the glint of a smooth surface
//    is a firefly no sample count tames); at each scattering inside a grain,
//    through the one flat facet of the grain's mesh whose refraction of the sun's parallel
//    rays passes there (found by fixed-point iteration, then a shadow ray from the facet;
//    `suns_through_facets`); and when a path leaves the scene inside the sun's cone after a
//    smooth event not followed by such gathering. Light of a sun that reaches a scattering
//    only after an internal reflection is left out (measured in the tests: within 2% on a
//    sphere). Without the facets, light through grains would come only from paths that meet
//    the disc, which with the real sun's 0.27° almost never happens;
//  - a quad light, through shadow rays from diffuse surfaces, or when a path meets it right
//    after a smooth event (the camera's ray included);
// Paths end by Russian roulette on their throughput after three surface events, and after
// `max_depth` surface events (the ray leaving the last one is traced for the sky and lights
// it meets); a walk inside a grain ends after `max_scatterings` (that light
// is lost: stats count them).
//
// Every random number is the pixel sampler's (sampler.hpp), dimension pairs in the order the
// path uses them, so an image depends only on the seed, never on the thread count; tiles of
// kTileSize² pixels (image_tiles.hpp). Written by hand: Mitsuba and pbrt are not packaged for
// Debian, and Embree only answers ray queries.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "shading/adaptive_sampling.hpp"
#include "shading/camera.hpp"
#include "shading/cdrf.hpp"
#include "shading/image.hpp"
#include "shading/lights.hpp"
#include "shading/material.hpp"
#include "shading/random_walk.hpp"
#include "shading/render_scene.hpp"
#include "shading/image_tiles.hpp"
#include "shading/sampler.hpp"

namespace rice::shading {

struct PathTraceSettings {
  int width = 640, height = 480;
  int samples_per_pixel = 64;
  SamplerKind sampler = SamplerKind::kSobol;
  std::uint64_t seed = 1;
  int max_depth = 64;  ///< surface events (reflections, refractions, bounces) per path, ≥ 1
  long long max_scatterings = 100'000;  ///< scatterings of one walk inside a grain
  /// Suns gathered at each scattering inside a grain through the facet that refracts their
  /// light there (see the file comment); false: only by paths that meet their disc.
  bool suns_through_facets = true;
  /// The suns' reflection off a grain is the material's rough GGX lobe, gathered by shadow
  /// rays where a path meets the grain from outside, as the fast models' is; false: off the
  /// smooth boundary, seen only by the rare path that meets a sun's disc (fireflies).
  bool rough_sun_glints = true;
  /// Set: a rice material without a medium is the fast model (the CDRF, and its translucency
  /// when set; material.hpp) instead of Lambertian, each bounce sampling its response. The
  /// table outlives the render.
  const CdrfTable* cdrf = nullptr;
  PixelWindow crop{};  ///< render only these pixels, into an image of the crop's size (empty: all)
  AdaptiveSampling adaptive{};  ///< off: every pixel takes samples_per_pixel (adaptive_sampling.hpp)
};

struct PathTraceStats {
  long long paths = 0, rays = 0, scatterings = 0;
  long long walks_cut = 0;  ///< walks ended at max_scatterings
  long long walks_lost = 0;  ///< walks whose ray found no surface of their grain (an open mesh)
  double seconds = 0.0;
};

/// Renders with path tracing. `media[m]` is the medium inside material m's surfaces (a rice
/// grain) or empty (a surface); `media` may be shorter than `materials` (the rest are
/// surfaces). `progress` and `cancelled` as in renderer.hpp. Throws std::invalid_argument for
/// sizes, sample counts or depths below 1, an instance's material outside `materials`, or a
/// medium with negative coefficients, σ_t = 0, |g| ≥ 1 or η ≤ 0.
Image path_trace(const RenderScene& scene, const std::vector<Material>& materials,
                 const std::vector<std::optional<Medium>>& media, const Lights& lights, const Camera& camera,
                 const PathTraceSettings& settings, PathTraceStats* stats = nullptr,
                 const std::function<void(int done, int total)>& progress = {},
                 const std::function<bool()>& cancelled = {});

}  // namespace rice::shading
