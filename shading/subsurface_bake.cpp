// Photon-traced subsurface reference on meshes (subsurface_bake.hpp).
#include "shading/subsurface_bake.hpp"

#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>

#include "shading/fresnel.hpp"
#include "shading/scattering.hpp"
#include "shading/tangent_frame.hpp"

namespace rice::shading {
namespace {

using Eigen::Vector3d;
using Eigen::Vector3f;

// A light as the bake sees it: a sun (sampled over its disc as the renderer does) or the
// uniform sky (sampled over the sphere), and what its photons carry per unit disc area:
// E for a sun, L 4π for the sky.
struct PhotonSource {
  const Sun* sun = nullptr;  // null: the sky
  Sun::Sampler sun_sampler;
  double carried = 0.0;
};

// Where light that leaves grain `instance` at x along d goes next: back into the same grain
// (a pore inside it, or a dent of its surface it faces), after bouncing between that
// grain's walls by Fresnel reflection as chance picks, or away (nullopt). Re-entry returns
// the point just inside and the refracted direction.
struct Reentry {
  Vector3d x, d;
};
std::optional<Reentry> follow_outside(const RenderScene& scene, int instance, double eta, Vector3d x, Vector3d d,
                                      std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const float offset = scene.ray_offset();
  for (int bounce = 0; bounce < 100; ++bounce) {
    const auto wall = scene.intersect_instance({x.cast<float>(), d.cast<float>()}, instance);
    if (!wall) return std::nullopt;
    const Vector3d n = wall->geometric_normal.cast<double>();
    if (d.dot(n) >= 0.0) return std::nullopt;  // met its wall from inside: a crack in the mesh
    if (unit(rng) < fresnel_reflectance(-d.dot(n), eta)) {
      d -= 2.0 * d.dot(n) * n;
      x = wall->position.cast<double>() + offset * n;
      continue;
    }
    return Reentry{wall->position.cast<double>() - offset * n, refract(d, n, eta)};
  }
  return std::nullopt;
}

// Walks one photon from its entry; splats escaping flux (times `flux`) onto `tally` where it
// leaves for good. Light that leaves into a pore or a dent of the same grain is followed back
// in (follow_outside): on a porous grain most of it does.
void walk(const RenderScene& scene, int instance, const Medium& medium, const ShadingPoint& entry,
          const Vector3d& travel, double flux, std::mt19937_64& rng, std::vector<double>& tally) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double eta = medium.refractive_index;
  const double sigma_t = medium.scattering + medium.absorption;
  const double survival = medium.scattering / sigma_t;
  const float offset = scene.ray_offset();
  const Vector3d n = entry.geometric_normal.cast<double>();
  double weight = flux * (1.0 - fresnel_reflectance(-travel.dot(n), eta));
  Vector3d d = refract(travel, n, eta);
  Vector3d x = entry.position.cast<double>() - offset * n;
  bool scattered = false;  // light crossing without scattering is refraction, not tallied
  constexpr int kMaxEvents = 100'000;
  for (int event = 0; event < kMaxEvents && weight > 0.0; ++event) {
    const auto boundary = scene.intersect({x.cast<float>(), d.cast<float>()});
    if (!boundary) return;  // left through a crack in the mesh: lost
    const double free_path = -std::log(1.0 - unit(rng)) / sigma_t;
    if (free_path < boundary->t) {
      x += free_path * d;
      weight *= survival;
      d = rotate_about(d, sample_henyey_greenstein(medium.anisotropy, unit(rng)), 2 * std::numbers::pi * unit(rng));
      scattered = true;
    } else {
      if (boundary->instance != instance) return;  // into another body (an overlap): lost
      const Vector3d normal = boundary->geometric_normal.cast<double>();
      const double reflectance = fresnel_reflectance(d.dot(normal), 1.0 / eta);
      const Vector3d out_direction = refract(d, normal, 1.0 / eta);
      const Vector3d outside = boundary->position.cast<double>() + offset * normal;
      if (reflectance < 1.0) {
        if (const std::optional<Reentry> back = follow_outside(scene, instance, eta, outside, out_direction, rng)) {
          if (unit(rng) >= reflectance) {  // out, and back in elsewhere
            x = back->x;
            d = back->d;
            continue;
          }
        } else {  // out for good: the transmitted part leaves here
          if (scattered) {
            const Eigen::Vector3i tri = scene.triangle(instance, boundary->primitive);
            for (int k = 0; k < 3; ++k) tally[tri[k]] += weight * (1.0 - reflectance) * boundary->barycentric[k];
          }
          weight *= reflectance;
        }
      }
      x = boundary->position.cast<double>() - offset * normal;
      d -= 2.0 * d.dot(normal) * normal;
    }
    if (weight < 1e-4 * flux) {  // Russian roulette
      if (unit(rng) < 0.1) weight *= 10.0;
      else weight = 0.0;
    }
  }
}

}  // namespace

std::vector<std::vector<float>> bake_subsurface(RenderScene& scene, const std::vector<int>& instances,
                                                const std::vector<Medium>& media, const Lights& lights,
                                                const BakeSettings& settings, BakeStats* stats) {
  if (instances.size() != media.size()) throw std::invalid_argument("bake_subsurface: one medium per instance");
  if (settings.photons_per_light < 1 || settings.batch < 1)
    throw std::invalid_argument("bake_subsurface: photons and batch must be at least 1");
  if (!lights.environment.image.empty())
    throw std::invalid_argument("bake_subsurface: sky images are not supported, only a uniform sky");
  const auto start = std::chrono::steady_clock::now();
  // The media are grey, so one walk serves all three channels: the light's mean.
  std::vector<PhotonSource> sources;
  for (const Sun& sun : lights.suns) sources.push_back({&sun, sun.sampler(), sun.irradiance.mean()});
  if (!lights.environment.empty()) sources.push_back({nullptr, {}, 4.0 * std::numbers::pi * lights.environment.constant.mean()});

  std::vector<std::vector<float>> exitance;
  long long traced = 0;
  for (std::size_t k = 0; k < instances.size(); ++k) {
    const int instance = instances[k];
    const auto sphere = scene.bounding_sphere(instance);  // no structured binding: lambdas capture these
    const Eigen::Vector3f centre = sphere.first;
    const float radius = sphere.second;
    // Flux per photon over the disc of area π R² (per colour channel, grey media here):
    // sun E π R² / N; sky L π R² 4π / N (directions uniform over the sphere).
    std::vector<double> sum(static_cast<std::size_t>(scene.vertex_count(instance)), 0.0);
    for (std::size_t s = 0; s < sources.size(); ++s) {
      const PhotonSource& source = sources[s];
      const double disc = std::numbers::pi * radius * radius;
      const double flux = disc * source.carried / static_cast<double>(settings.photons_per_light);
      const long long batches = (settings.photons_per_light + settings.batch - 1) / settings.batch;
      std::vector<std::vector<double>> partial(static_cast<std::size_t>(batches));
      tbb::parallel_for(0LL, batches, [&](long long b) {
        std::vector<double> tally(sum.size(), 0.0);
        std::mt19937_64 rng(split_mix(settings.seed ^ split_mix((k << 40) ^ (s << 32) ^ static_cast<std::uint64_t>(b))));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const long long n = std::min<long long>(settings.batch, settings.photons_per_light - b * settings.batch);
        for (long long p = 0; p < n; ++p) {
          Vector3d towards = source.sun_sampler.w;  // a sun without size: its axis
          if (!source.sun || source.sun->angular_radius > 0.0f) {
            const double a = unit(rng), b = unit(rng);
            towards = source.sun ? source.sun_sampler.direction(a, b) : Environment::direction(a, b);
          }
          const auto [u, v] = tangent_frame(towards);
          const double rho = radius * std::sqrt(unit(rng)), angle = 2 * std::numbers::pi * unit(rng);
          const Vector3d origin = centre.cast<double>() + 2.0 * radius * towards +
                                  rho * (std::cos(angle) * u + std::sin(angle) * v);
          const auto hit = scene.intersect({origin.cast<float>(), (-towards).cast<float>()});
          if (!hit || hit->instance != instance) continue;  // missed it, or something else is in the way
          walk(scene, instance, media[k], *hit, -towards, flux, rng, tally);
        }
        partial[b] = std::move(tally);
      });
      for (const auto& tally : partial)
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += tally[i];
      traced += settings.photons_per_light;
    }
    const std::vector<double> area = scene.vertex_areas(instance);
    std::vector<float> m(sum.size()), radiance(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
      m[i] = area[i] > 0.0 ? static_cast<float>(sum[i] / area[i]) : 0.0f;
      radiance[i] = static_cast<float>(m[i] / std::numbers::pi);
    }
    scene.set_vertex_values(instance, std::move(radiance));
    exitance.push_back(std::move(m));
  }
  if (stats) {
    stats->photons = traced;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return exitance;
}

}  // namespace rice::shading
