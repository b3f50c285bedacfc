// Direct-lighting renderer over Embree (renderer.hpp).
#include "shading/renderer.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>

namespace rice::shading {

namespace {

struct Counters {
  long long camera = 0, shadow = 0;
};

// Radiance towards −ray.direction from the first surface along the camera ray. Sample pairs:
// 0 pixel, 1 lens, then one per sun, one per quad light, one for the environment, one for
// the specular lobe.
Color shade(const RenderScene& scene, const std::vector<Material>& materials, const Lights& lights,
            const std::vector<Sun::Sampler>& suns, const CdrfTable& cdrf, const RenderSettings& settings,
            const PixelSampler& sampler, int index, const Ray& ray, Counters& counters) {
  const std::optional<ShadingPoint> hit = scene.intersect(ray);
  ++counters.camera;
  if (!hit) return lights.environment.radiance(ray.direction);
  const Material& material = materials[hit->material];
  const Eigen::Vector3f wo = -ray.direction;
  Eigen::Vector3f ng = hit->geometric_normal, n = hit->shading_normal;
  if (ng.dot(wo) < 0.0f) {  // seen from behind (an open mesh, or a ray inside): face the viewer
    ng = -ng;
    n = -n;
  }
  const int self = material.kind == MaterialKind::kRice ? hit->instance : -1;  // see renderer.hpp
  const float offset = scene.ray_offset();
  auto visible = [&](const Eigen::Vector3f& wi, float distance, bool test) {
    if (!test) return true;
    ++counters.shadow;
    const Eigen::Vector3f origin = hit->position + (ng.dot(wi) >= 0.0f ? offset : -offset) * ng;
    return !scene.occluded({origin, wi, 0.0f, distance * (1.0f - 1e-4f)}, self);
  };

  Color radiance = Color::Zero();
  if (material.kind == MaterialKind::kSubsurfaceReference) radiance += static_cast<float>(hit->baked);
  // Adds a light sample's unoccluded contribution c after its visibility test. Shadow-ray
  // roulette: a contribution small against what this sample has gathered so far, R, is
  // tested with probability p = min(1, 4c / (R + c)) and weighted 1/p, which keeps the
  // estimate unbiased and spares most rays of the dim sky and Fresnel-weak specular samples
  // on sunlit grains. Its random numbers come from their own sample dimensions.
  int roulette_pair = 64;
  auto add = [&](const Color& contribution, const Eigen::Vector3f& wi, float distance, bool test) {
    if (!(contribution > 0.0f).any()) return;
    if (!test) {
      radiance += contribution;
      return;
    }
    const double c = contribution.mean(), gathered = radiance.mean();
    const double p = std::min(1.0, 4.0 * c / (gathered + c));
    double u = 0.0, unused = 0.0;
    sampler.pair(index, roulette_pair++, u, unused);
    if (u >= p) return;
    if (visible(wi, distance, true)) radiance += contribution / static_cast<float>(p);
  };
  int pair = 2;
  double a = 0.0, b = 0.0;
  for (const Sun::Sampler& sun : suns) {
    sampler.pair(index, pair++, a, b);
    const LightSample s = sun.sample(a, b);
    add(surface_response(material, cdrf, n, wo, s.direction, hit->curvature) * s.weight, s.direction, s.distance,
        settings.shadows);
  }
  for (const QuadLight& quad : lights.quads) {
    sampler.pair(index, pair++, a, b);
    const LightSample s = quad.sample(hit->position, a, b);
    if ((s.weight <= 0.0f).all()) continue;
    add(surface_response(material, cdrf, n, wo, s.direction, hit->curvature) * s.weight, s.direction, s.distance,
        settings.shadows);
  }
  if (!lights.environment.empty()) {
    // Diffuse part over the whole sphere; the specular part from its own lobe below.
    sampler.pair(index, pair++, a, b);
    const LightSample s = lights.environment.sample(a, b);
    add(diffuse_term(material, cdrf, n, wo, s.direction, hit->curvature) * s.weight, s.direction, s.distance,
        settings.ambient_occlusion);
    if (has_specular(material)) {
      sampler.pair(index, pair++, a, b);
      Eigen::Vector3f wi;
      const double weight = sample_specular(n, wo, material.refractive_index, material.roughness, a, b, wi);
      if (weight > 0.0)
        add(static_cast<float>(weight) * lights.environment.radiance(wi), wi, std::numeric_limits<float>::infinity(),
            settings.ambient_occlusion);
    }
  }
  return radiance;
}

}  // namespace

Image render(const RenderScene& scene, const std::vector<Material>& materials, const Lights& lights,
             const Camera& camera, const CdrfTable& cdrf, const RenderSettings& settings, RenderStats* stats,
             const std::function<void(int, int)>& progress, const std::function<bool()>& cancelled) {
  if (settings.width < 1 || settings.height < 1 || settings.samples_per_pixel < 1)
    throw std::invalid_argument("render: width, height and samples per pixel must be at least 1");
  if (materials.empty()) throw std::invalid_argument("render: no materials");
  // Material indices are checked here, once, rather than per hit.
  for (int i = 0; i < scene.instance_count(); ++i) {
    const int m = scene.material_of(i);
    if (m < 0 || m >= static_cast<int>(materials.size()))
      throw std::invalid_argument("render: instance " + std::to_string(i) + " has material " + std::to_string(m) +
                                  " of " + std::to_string(materials.size()));
  }
  const auto start = std::chrono::steady_clock::now();
  Image image(settings.width, settings.height);
  const int tiles_x = (settings.width + kTileSize - 1) / kTileSize;
  const int tiles = tile_count(settings);
  std::atomic<int> done = 0;
  std::atomic<long long> camera_rays = 0, shadow_rays = 0;
  const Camera::Frame frame = camera.frame(static_cast<double>(settings.width) / settings.height);
  std::vector<Sun::Sampler> suns;
  for (const Sun& sun : lights.suns) suns.push_back(sun.sampler());
  tbb::parallel_for(0, tiles, [&](int tile) {
    if (cancelled && cancelled()) return;
    Counters counters;
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    for (int y = y0; y < std::min(y0 + kTileSize, settings.height); ++y) {
      for (int x = x0; x < std::min(x0 + kTileSize, settings.width); ++x) {
        const PixelSampler sampler(settings.sampler, settings.seed, x, y, settings.samples_per_pixel);
        Color sum = Color::Zero();
        for (int i = 0; i < settings.samples_per_pixel; ++i) {
          double px = 0.0, py = 0.0, la = 0.0, lb = 0.0;
          sampler.pair(i, 0, px, py);
          sampler.pair(i, 1, la, lb);
          const CameraRay cr = frame.ray((x + px) / settings.width, (y + py) / settings.height, la, lb);
          sum += shade(scene, materials, lights, suns, cdrf, settings, sampler, i, {cr.origin, cr.direction}, counters);
        }
        image.at(x, y) = sum / static_cast<float>(settings.samples_per_pixel);
      }
    }
    camera_rays += counters.camera;
    shadow_rays += counters.shadow;
    const int finished = ++done;
    if (progress) progress(finished, tiles);
  });
  if (stats) {
    stats->camera_rays = camera_rays;
    stats->shadow_rays = shadow_rays;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

}  // namespace rice::shading
