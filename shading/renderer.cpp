// Direct-lighting renderer over Embree (renderer.hpp).
#include "shading/renderer.hpp"

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

// What shading needs of one camera sample's first hit. Sample pairs: 0 pixel, 1 lens, then
// one per sun, one per quad light, one for the environment, one for the specular lobe;
// shadow-ray roulette draws from pairs 64 on.
struct SurfaceSample {
  const ShadingPoint* hit = nullptr;  // null: the ray left the scene
  const Material* material = nullptr;
  Eigen::Vector3f wo, ng, n;  // towards the camera; normals turned to face it
  int self = -1;              // the instance its shadow rays see through (rice), or −1
  Color radiance = Color::Zero();
};

SurfaceSample surface_sample(const std::vector<Material>& materials, const Ray& ray, const std::optional<ShadingPoint>& hit) {
  SurfaceSample s;
  if (!hit) return s;
  s.hit = &*hit;
  s.material = &materials[hit->material];
  s.wo = -ray.direction;
  s.ng = hit->geometric_normal;
  s.n = hit->shading_normal;
  if (s.ng.dot(s.wo) < 0.0f) {  // seen from behind (an open mesh, or a ray inside): face the viewer
    s.ng = -s.ng;
    s.n = -s.n;
  }
  s.self = s.material->kind == MaterialKind::kRice ? hit->instance : -1;  // see renderer.hpp
  if (s.material->kind == MaterialKind::kSubsurfaceReference) s.radiance += static_cast<float>(hit->baked);
  return s;
}

// A shadow ray from the surface towards wi, offset to the side wi leaves on.
Ray shadow_ray(const RenderScene& scene, const SurfaceSample& s, const Eigen::Vector3f& wi, float distance) {
  const float offset = scene.ray_offset();
  return {s.hit->position + (s.ng.dot(wi) >= 0.0f ? offset : -offset) * s.ng, wi, 0.0f, distance * (1.0f - 1e-4f)};
}

// The lights after the suns (whose shadow rays the caller traced together): area lights and
// the environment, each shadow ray on its own.
void shade_remaining_lights(const RenderScene& scene, const Lights& lights, const CdrfTable& cdrf,
                            const RenderSettings& settings, const PixelSampler& sampler, int index, int first_pair,
                            SurfaceSample& s, Counters& counters) {
  const Material& material = *s.material;
  const ShadingPoint& hit = *s.hit;
  // Adds a light sample's unoccluded contribution c after its visibility test. Shadow-ray
  // roulette: a contribution small against what this sample has gathered so far, R, is
  // tested with probability p = min(1, 4c / (R + c)) and weighted 1/p, which keeps the
  // estimate unbiased and spares most rays of the dim sky and Fresnel-weak specular samples
  // on sunlit grains.
  int roulette_pair = 64;
  auto add = [&](const Color& contribution, const Eigen::Vector3f& wi, float distance, bool test) {
    if (!(contribution > 0.0f).any()) return;
    if (!test) {
      s.radiance += contribution;
      return;
    }
    const double c = contribution.mean(), gathered = s.radiance.mean();
    const double p = std::min(1.0, 4.0 * c / (gathered + c));
    double u = 0.0, unused = 0.0;
    sampler.pair(index, roulette_pair++, u, unused);
    if (u >= p) return;
    ++counters.shadow;
    if (!scene.occluded(shadow_ray(scene, s, wi, distance), s.self)) s.radiance += contribution / static_cast<float>(p);
  };
  int pair = first_pair;
  double a = 0.0, b = 0.0;
  for (const QuadLight& quad : lights.quads) {
    sampler.pair(index, pair++, a, b);
    const LightSample l = quad.sample(hit.position, a, b);
    if ((l.weight <= 0.0f).all()) continue;
    add(surface_response(material, cdrf, s.n, s.wo, l.direction, hit.curvature, hit.thickness) * l.weight, l.direction, l.distance,
        settings.shadows);
  }
  if (lights.environment.empty()) return;
  // Diffuse part over the whole sphere; the specular part from its own lobe below.
  sampler.pair(index, pair++, a, b);
  const LightSample l = lights.environment.sample(a, b);
  add(diffuse_term(material, cdrf, s.n, s.wo, l.direction, hit.curvature, hit.thickness) * l.weight, l.direction, l.distance,
      settings.ambient_occlusion);
  if (has_specular(material)) {
    sampler.pair(index, pair++, a, b);
    Eigen::Vector3f wi;
    const Color weight = sample_specular(material, s.n, s.wo, a, b, wi);
    if ((weight > 0.0f).any())
      add(weight * lights.environment.radiance(wi), wi, std::numeric_limits<float>::infinity(),
          settings.ambient_occlusion);
  }
}

// Scratch space of one thread: a batch of a pixel's samples.
struct Batch {
  std::vector<Ray> rays, sun_rays;
  std::vector<std::optional<ShadingPoint>> hits;
  std::vector<SurfaceSample> samples;
  std::vector<int> sun_ignore, sun_sample;
  std::vector<Color> sun_contribution;
  std::vector<char> sun_occluded;
};

// What every sample of an image reads.
struct DirectContext {
  const RenderScene& scene;
  const std::vector<Material>& materials;
  const Lights& lights;
  std::vector<Sun::Sampler> suns;
  const CdrfTable& cdrf;
  const RenderSettings& settings;
  Camera::Frame frame;
};

// The radiance of samples [first, first + count) of one pixel, added to `sums`. Their camera
// rays go to Embree together as a coherent stream, and so do their shadow rays towards the suns.
void shade_batch(const DirectContext& c, const PixelSampler& sampler, int x, int y, int first, int count,
                 Batch& batch, Counters& counters, PixelSums& sums) {
  const RenderScene& scene = c.scene;
  const Lights& lights = c.lights;
  const std::vector<Sun::Sampler>& suns = c.suns;
  const CdrfTable& cdrf = c.cdrf;
  const RenderSettings& settings = c.settings;
  batch.rays.clear();
  for (int i = first; i < first + count; ++i) {
    double px = 0.0, py = 0.0, la = 0.0, lb = 0.0;
    sampler.pair(i, 0, px, py);
    sampler.pair(i, 1, la, lb);
    const CameraRay cr = c.frame.ray((x + px) / settings.width, (y + py) / settings.height, la, lb);
    batch.rays.push_back({cr.origin, cr.direction});
  }
  scene.intersect_coherent(batch.rays, batch.hits);
  counters.camera += count;

  batch.samples.clear();
  batch.sun_rays.clear();
  batch.sun_ignore.clear();
  batch.sun_sample.clear();
  batch.sun_contribution.clear();
  for (int k = 0; k < count; ++k) {
    batch.samples.push_back(surface_sample(c.materials, batch.rays[k], batch.hits[k]));
    SurfaceSample& s = batch.samples.back();
    if (!s.hit) continue;
    for (std::size_t j = 0; j < suns.size(); ++j) {
      double a = 0.0, b = 0.0;
      sampler.pair(first + k, 2 + static_cast<int>(j), a, b);
      const LightSample l = suns[j].sample(a, b);
      const Color c = surface_response(*s.material, cdrf, s.n, s.wo, l.direction, s.hit->curvature, s.hit->thickness) * l.weight;
      if (!(c > 0.0f).any()) continue;
      if (!settings.shadows) {
        s.radiance += c;
        continue;
      }
      batch.sun_rays.push_back(shadow_ray(scene, s, l.direction, l.distance));
      batch.sun_ignore.push_back(s.self);
      batch.sun_sample.push_back(k);
      batch.sun_contribution.push_back(c);
    }
  }
  if (!batch.sun_rays.empty()) {
    scene.occluded_many(batch.sun_rays, batch.sun_ignore, batch.sun_occluded);
    counters.shadow += static_cast<long long>(batch.sun_rays.size());
    for (std::size_t r = 0; r < batch.sun_rays.size(); ++r)
      if (!batch.sun_occluded[r]) batch.samples[batch.sun_sample[r]].radiance += batch.sun_contribution[r];
  }

  for (int k = 0; k < count; ++k) {
    SurfaceSample& s = batch.samples[k];
    if (!s.hit) {
      sums.add(lights.environment.radiance(batch.rays[k].direction));
      continue;
    }
    shade_remaining_lights(scene, lights, cdrf, settings, sampler, first + k, 2 + static_cast<int>(suns.size()), s,
                           counters);
    sums.add(s.radiance);
  }
}

}  // namespace

Image render(const RenderScene& scene, const std::vector<Material>& materials, const Lights& lights,
             const Camera& camera, const CdrfTable& cdrf, const RenderSettings& settings, RenderStats* stats,
             const std::function<void(int, int)>& progress, const std::function<bool()>& cancelled) {
  if (settings.width < 1 || settings.height < 1 || settings.samples_per_pixel < 1)
    throw std::invalid_argument("render: width, height and samples per pixel must be at least 1");
  validate(settings.adaptive, "render");
  check_instance_materials(scene, materials.size(), "render");
  const auto start = std::chrono::steady_clock::now();
  const PixelWindow window = rendered_pixels(settings.width, settings.height, settings.crop, "render");
  DirectContext context{scene, materials, lights, {}, cdrf, settings,
                        camera.frame(static_cast<double>(settings.width) / settings.height)};
  for (const Sun& sun : lights.suns) context.suns.push_back(sun.sampler());
  std::atomic<long long> camera_rays = 0, shadow_rays = 0;
  // A tile's sampler: a pixel's samples in batches of up to 64, and its ray counts.
  struct TileSampler {
    const DirectContext& context;
    std::atomic<long long>&camera_rays, &shadow_rays;
    Batch batch{};
    Counters counters{};
    void operator()(int x, int y, int first, int count, PixelSums& sums) {
      const RenderSettings& s = context.settings;
      const PixelSampler sampler(s.sampler, s.seed, x, y, s.samples_per_pixel);
      constexpr int kBatch = 64;
      for (int i = first; i < first + count; i += kBatch)
        shade_batch(context, sampler, x, y, i, std::min(kBatch, first + count - i), batch, counters, sums);
    }
    void finish() {
      camera_rays += counters.camera;
      shadow_rays += counters.shadow;
    }
  };
  const Image image = sample_pixels(settings.width, settings.height, window, settings.samples_per_pixel,
                                    settings.adaptive, progress, cancelled,
                                    [&] { return TileSampler{context, camera_rays, shadow_rays}; });
  if (stats) {
    stats->camera_rays = camera_rays;
    stats->shadow_rays = shadow_rays;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

}  // namespace rice::shading
