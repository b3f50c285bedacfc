// The subsurface-scattering reference on meshes: photons from the scene's suns and sky are
// traced into each rice grain (Embree finds the surface from outside and from inside), walk
// through its medium as in random_walk.hpp (Fresnel entry and exit, exponential free paths,
// Henyey–Greenstein scattering, survival σ_s/σ_t), and where they escape their flux is
// splatted onto the triangle's vertices. Divided by each vertex's area this is the
// exitance M, and a grain seen from anywhere has diffuse radiance M/π (the exit is taken as
// Lambertian, as the CDRF's is): the reference image the CDRF is measured against.
//
// Photons of an instance start on a disc that covers its bounding sphere, perpendicular to
// the light; one that meets other geometry first is that geometry's shadow and is dropped.
// A photon that leaves a grain is not followed further (no light bounces between grains,
// as in the CDRF render); nor is light that crosses a grain without scattering (refraction,
// left out as in random_walk.hpp). The media are grey: the lights' colours are averaged.
// Deterministic for a seed on any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "shading/lights.hpp"
#include "shading/random_walk.hpp"
#include "shading/render_scene.hpp"

namespace rice::shading {

struct BakeSettings {
  long long photons_per_light = 1'000'000;  ///< per instance, per sun and for the sky
  std::uint64_t seed = 1;
  int batch = 20'000;
};

struct BakeStats {
  long long photons = 0;
  double seconds = 0.0;
};

/// Exitance M [radiance·sr, the lights' units] at each vertex of each listed instance, with
/// `media[k]` the medium of `instances[k]`; also stored in the scene with set_vertex_values
/// as M/π (the diffuse radiance). Throws std::invalid_argument for mismatched lists.
std::vector<std::vector<float>> bake_subsurface(RenderScene& scene, const std::vector<int>& instances,
                                                const std::vector<Medium>& media, const Lights& lights,
                                                const BakeSettings& settings, BakeStats* stats = nullptr);

}  // namespace rice::shading
