// Path tracing through grains, the reference integrator (path_tracer.hpp).
#include "shading/path_tracer.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "shading/adaptive_sampling.hpp"
#include "shading/fresnel.hpp"
#include "shading/image_tiles.hpp"
#include "shading/scattering.hpp"
#include "shading/tangent_frame.hpp"

namespace rice::shading {
namespace {

using Eigen::Vector3d;
using Eigen::Vector3f;

struct PathCounters {
  long long paths = 0, rays = 0, scatterings = 0, walks_cut = 0, walks_lost = 0;
  PathCounters& operator+=(const PathCounters& o) {
    paths += o.paths;
    rays += o.rays;
    scatterings += o.scatterings;
    walks_cut += o.walks_cut;
    walks_lost += o.walks_lost;
    return *this;
  }
};

/// What every path of an image reads.
struct PathContext {
  const RenderScene& scene;
  const std::vector<Material>& materials;
  const std::vector<std::optional<Medium>>& media;
  const Lights& lights;
  std::vector<Sun::Sampler> suns;
  const PathTraceSettings& settings;
};

/// The sample stream of one path: successive dimension pairs of the pixel sampler.
struct PathSampler {
  const PixelSampler& pixel;
  int index;
  int next_pair = 2;  // 0: the pixel position, 1: the lens
  std::pair<double, double> pair() {
    double a = 0.0, b = 0.0;
    pixel.pair(index, next_pair++, a, b);
    return {a, b};
  }
};

const Medium* medium_of(const PathContext& c, int material) {
  return material < static_cast<int>(c.media.size()) && c.media[material] ? &*c.media[material] : nullptr;
}

/// Radiance of the suns' discs seen along d (each uniform, L = E / (π sin²α)).
Color sun_discs(const PathContext& c, const Vector3f& d) {
  Color L = Color::Zero();
  for (std::size_t k = 0; k < c.suns.size(); ++k) {
    const Sun::Sampler& s = c.suns[k];
    if (1.0 - s.w.dot(d.cast<double>()) > s.one_minus_cos_max) continue;
    const double solid_angle = 2.0 * std::numbers::pi * s.one_minus_cos_max;
    L += s.weight / static_cast<float>(solid_angle);  // weight = L · solid angle (pdf uniform)
  }
  return L;
}

/// Radiance of the nearest quad light the ray meets before `t_max` (Möller–Trumbore on the
/// parallelogram corner + s·edge_u + t·edge_v, s, t in [0, 1]; it emits on the side
/// edge_v × edge_u points to), or nothing.
Color quad_light(const PathContext& c, const Ray& ray, float t_max) {
  Color L = Color::Zero();
  float nearest = t_max;
  for (const QuadLight& quad : c.lights.quads) {
    const Vector3f p = ray.direction.cross(quad.edge_v);
    const float det = quad.edge_u.dot(p);
    if (std::abs(det) < 1e-20f) continue;
    const Vector3f to_origin = ray.origin - quad.corner;
    const float s = to_origin.dot(p) / det;
    const Vector3f q = to_origin.cross(quad.edge_u);
    const float t = ray.direction.dot(q) / det, distance = quad.edge_v.dot(q) / det;
    if (s < 0.0f || s > 1.0f || t < 0.0f || t > 1.0f || distance <= 0.0f || distance >= nearest) continue;
    if (quad.edge_v.cross(quad.edge_u).dot(ray.direction) >= 0.0f) continue;  // its back
    nearest = distance;
    L = quad.radiance;
  }
  return L;
}

/// A ray leaving a surface point along d, offset to the side d goes.
Ray leaving(const RenderScene& scene, const Vector3f& p, const Vector3f& ng, const Vector3f& d) {
  const float offset = scene.ray_offset();
  return {p + (ng.dot(d) >= 0.0f ? offset : -offset) * ng, d};
}

/// One sample of each sun and each quad light seen from p, in the path's sample order.
template <typename Add>
void for_each_light_sample(const PathContext& c, const Vector3f& p, PathSampler& sampler, const Add& add) {
  for (const Sun::Sampler& sun : c.suns) {
    const auto [a, b] = sampler.pair();
    add(sun.sample(a, b));
  }
  for (const QuadLight& quad : c.lights.quads) {
    const auto [a, b] = sampler.pair();
    add(quad.sample(p, a, b));
  }
}

/// Direct light at a Lambertian point (normal n facing the path, albedo A): suns and quads by
/// shadow rays, f = A/π, each light one sample.
Color direct_light(const PathContext& c, const ShadingPoint& hit, const Vector3f& n, const Color& albedo,
                   PathSampler& sampler, PathCounters& counters) {
  Color L = Color::Zero();
  const auto add = [&](const LightSample& l) {
    const float cos_i = n.dot(l.direction);
    if (cos_i <= 0.0f || (l.weight <= 0.0f).all()) return;
    Ray shadow = leaving(c.scene, hit.position, n, l.direction);
    shadow.t_max = l.distance * (1.0f - 1e-4f);
    ++counters.rays;
    if (!c.scene.occluded(shadow)) L += albedo * l.weight * (cos_i / std::numbers::pi_v<float>);
  };
  for_each_light_sample(c, hit.position, sampler, add);
  return L;
}

/// A cosine-weighted direction about unit n.
Vector3f cosine_direction(const Vector3f& n, double a, double b) {
  const double r = std::sqrt(a), phi = 2.0 * std::numbers::pi * b;
  const auto [t, s] = tangent_frame(n);
  const float z = static_cast<float>(std::sqrt(std::max(0.0, 1.0 - a)));
  return (static_cast<float>(r * std::cos(phi)) * t + static_cast<float>(r * std::sin(phi)) * s + z * n).normalized();
}

/// Henyey–Greenstein's phase function at cos θ, per steradian.
double henyey_greenstein(double g, double cos_theta) {
  const double denominator = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (4.0 * std::numbers::pi * denominator * std::sqrt(denominator));
}

/// The light of a sun's ray ω (weight E, its irradiance at normal incidence) that refracts in
/// at a facet (outward normal n, at distance s from x along −t, t the refracted direction)
/// and scatters at x towards −`arriving`:
///   L = p(t · (−arriving)) E T (cos θ_i / cos θ_t) e^{−σ_t s} / η²,
/// E T cos θ_i / cos θ_t being the beam's irradiance inside; over η², since the paths carry
/// radiance across a grain's boundary without the η² each crossing scales it by (they cancel
/// on a path that enters and leaves, and this light leaves by the camera's path). Zero if
/// something outside blocks the facet from the sun.
Color facet_light(const PathContext& c, const Medium& m, const Vector3d& arriving, const LightSample& sun,
                  const Vector3f& entry, const Vector3d& n, const Vector3d& t, double s, PathCounters& counters) {
  const Vector3d omega = sun.direction.cast<double>();
  const double eta = m.refractive_index, cos_i = omega.dot(n), cos_t = -t.dot(n);
  ++counters.rays;
  if (c.scene.occluded(leaving(c.scene, entry, n.cast<float>(), sun.direction))) return Color::Zero();
  const double inside = (1.0 - fresnel_reflectance(cos_i, eta)) * cos_i / (cos_t * eta * eta) *
                        std::exp(-(m.scattering + m.absorption) * s) * henyey_greenstein(m.anisotropy, t.dot(-arriving));
  return sun.weight * static_cast<float>(inside);
}

/// Where the line from x back along −t meets the triangle (Möller–Trumbore): its distance,
/// or a negative number.
double back_along(const std::array<Vector3f, 3>& triangle, const Vector3d& x, const Vector3d& t) {
  const Vector3d a = triangle[0].cast<double>(), e1 = triangle[1].cast<double>() - a, e2 = triangle[2].cast<double>() - a;
  const Vector3d d = -t, p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-30) return -1.0;
  const Vector3d to_x = x - a;
  const double u = to_x.dot(p) / det;
  const Vector3d q = to_x.cross(e1);
  const double v = d.dot(q) / det;
  if (u < 0.0 || v < 0.0 || u + v > 1.0) return -1.0;
  return e2.dot(q) / det;
}

/// A sun's light scattered at x (inside grain `instance`) towards −`arriving`, for its ray ω
/// (a sample of the sun). On a flat facet the sun's parallel rays refract into one direction
/// t; the facets whose refracted beam passes through x are found by iterating
/// d ← −refract(−ω, n(first facet along d)) from d = ω until the facet repeats, then among
/// that facet's neighbours (sharing a vertex): a curved surface focuses light, and on a mesh
/// that is beams of neighbouring facets overlapping (on a sphere, one facet alone gave 15%
/// too little). Light that reaches x only after an internal reflection is not found.
Color sun_through_facets(const PathContext& c, int instance, const Medium& m, const Vector3f& x,
                         const Vector3d& arriving, const LightSample& sun, PathCounters& counters) {
  const Vector3d omega = sun.direction.cast<double>(), xd = x.cast<double>();
  Vector3d d = omega;
  int facet = -1;
  for (int k = 0; k < 6; ++k) {
    ++counters.rays;
    const std::optional<ShadingPoint> entry = c.scene.intersect_instance({x, d.cast<float>()}, instance);
    if (!entry) return Color::Zero();
    const Vector3d n = entry->geometric_normal.cast<double>();
    if (entry->primitive != facet) {
      if (omega.dot(n) <= 0.0) return Color::Zero();  // the facet faces away from the sun
      d = -refract(-omega, n, m.refractive_index);
      facet = entry->primitive;
      continue;
    }
    Color light = facet_light(c, m, arriving, sun, entry->position, n, -d, entry->t, counters);
    thread_local std::vector<int> around;
    c.scene.triangles_around(instance, facet, around);
    for (const int other : around) {
      if (other == facet) continue;
      const std::array<Vector3f, 3> triangle = c.scene.world_triangle(instance, other);
      const Vector3d normal = (triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).cast<double>().normalized();
      if (omega.dot(normal) <= 0.0) continue;
      const Vector3d t = refract(-omega, normal, m.refractive_index);
      const double s = back_along(triangle, xd, t);
      if (s <= 0.0) continue;
      ++counters.rays;  // nothing of the grain between: the first facet back along −t is this one
      const std::optional<ShadingPoint> check = c.scene.intersect_instance({x, (-t).cast<float>()}, instance);
      if (!check || check->primitive != other) continue;
      light += facet_light(c, m, arriving, sun, check->position, normal, t, s, counters);
    }
    return light;
  }
  return Color::Zero();
}

/// What a walk brings out: the ray it leaves by (none: it ended inside), and whether it
/// scattered with the suns gathered at its scatterings (then a sun seen after it is counted).
struct WalkExit {
  std::optional<Ray> ray;
  bool suns_gathered = false;
};

/// The walk inside grain `instance` from its surface point p (outward geometric normal ng),
/// entering along d. Multiplies `throughput` by σ_s/σ_t at each scattering, where it adds the
/// suns' light through the facets to `radiance` (settings.suns_through_facets).
WalkExit walk(const PathContext& c, int instance, const Medium& m, Vector3f p, const Vector3f& ng, Vector3d d,
              Color& throughput, Color& radiance, PathSampler& sampler, PathCounters& counters) {
  WalkExit exit;
  const bool gather = c.settings.suns_through_facets && !c.suns.empty();
  const double sigma_t = m.scattering + m.absorption, survival = m.scattering / sigma_t;
  const float offset = c.scene.ray_offset();
  Vector3f origin = p - offset * ng;  // just inside
  for (long long scatterings = 0;;) {
    ++counters.rays;
    const std::optional<ShadingPoint> boundary = c.scene.intersect_instance({origin, d.cast<float>()}, instance);
    if (!boundary) {
      ++counters.walks_lost;
      return exit;
    }
    const auto [a, b] = sampler.pair();
    const double free_path = -std::log1p(-a) / sigma_t;
    if (free_path < boundary->t) {
      if (++scatterings > c.settings.max_scatterings) {
        ++counters.walks_cut;
        return exit;
      }
      ++counters.scatterings;
      origin += static_cast<float>(free_path) * d.cast<float>();
      throughput *= static_cast<float>(survival);
      if (gather) {
        for (const Sun::Sampler& sun : c.suns) {
          const auto [sa, sb] = sampler.pair();
          radiance += throughput * sun_through_facets(c, instance, m, origin, d, sun.sample(sa, sb), counters);
        }
      }
      exit.suns_gathered = gather;
      const auto [u, unused] = sampler.pair();
      d = rotate_about(d, sample_henyey_greenstein(m.anisotropy, b), 2.0 * std::numbers::pi * u);
      continue;
    }
    // At the boundary from inside: Fresnel from index η to 1 decides.
    const Vector3d n = boundary->geometric_normal.cast<double>();  // outward
    const double cos_inside = d.dot(n);
    const auto [r, unused] = sampler.pair();
    if (r < fresnel_reflectance(cos_inside, 1.0 / m.refractive_index)) {
      d = (d - 2.0 * cos_inside * n).normalized();
      origin = boundary->position - offset * boundary->geometric_normal;
      continue;
    }
    const Vector3f out = refract(d, n, 1.0 / m.refractive_index).cast<float>();
    exit.ray = Ray{boundary->position + offset * boundary->geometric_normal, out};
    return exit;
  }
}

/// Whether a surface is shaded by the fast rice model (the CDRF, with its translucency when
/// set) rather than walked through or taken as Lambertian.
bool fast_rice(const PathContext& c, const Material& m, const Medium* medium) {
  return !medium && m.kind == MaterialKind::kRice && c.settings.cdrf;
}

/// The suns and quads seen from a surface point, each one sample and a shadow ray: Σ f(ω_i) L_i
/// for f = `response` (f · cos θ_i as a function of ω_i). The shadow rays see through
/// instance `ignore` (-1: none).
template <typename Response>
Color shadowed_light(const PathContext& c, const ShadingPoint& hit, const Vector3f& ng, int ignore,
                     const Response& response, PathSampler& sampler, PathCounters& counters) {
  Color L = Color::Zero();
  const auto add = [&](const LightSample& l) {
    if ((l.weight <= 0.0f).all()) return;
    const Color f = response(l.direction);
    if (!(f > 0.0f).any()) return;
    Ray shadow = leaving(c.scene, hit.position, ng, l.direction);
    shadow.t_max = l.distance * (1.0f - 1e-4f);
    ++counters.rays;
    if (!c.scene.occluded(shadow, ignore)) L += f * l.weight;
  };
  for_each_light_sample(c, hit.position, sampler, add);
  return L;
}

/// Direct light at a fast-rice point: shadow rays that see through the grain itself (its light
/// past the terminator and through it is the model's), f the material's whole response,
/// diffuse and specular.
Color fast_rice_direct(const PathContext& c, const ShadingPoint& hit, const Material& m, const Vector3f& n,
                       const Vector3f& ng, const Vector3f& wo, PathSampler& sampler, PathCounters& counters) {
  const auto response = [&](const Vector3f& wi) {
    return surface_response(m, *c.settings.cdrf, n, wo, wi, hit.curvature, hit.thickness);
  };
  return shadowed_light(c, hit, ng, hit.instance, response, sampler, counters);
}

/// Direct light at a metal point (normal n facing ω_o): the suns and quads through its GGX lobe.
Color metal_direct(const PathContext& c, const ShadingPoint& hit, const Material& m, const Vector3f& n,
                   const Vector3f& ng, const Vector3f& wo, PathSampler& sampler, PathCounters& counters) {
  const auto response = [&](const Vector3f& wi) { return specular_term(m, n, wo, wi); };
  return shadowed_light(c, hit, ng, -1, response, sampler, counters);
}

/// The next direction from a fast-rice point and its weight f cos / (lobe probability · pdf):
/// the specular lobe with probability kSpecular, else the diffuse response, sampled by a
/// cosine about n (kFront), a cosine about −n (light through the grain; the CDRF also reaches
/// past the terminator) or uniformly over the sphere (kUniform), one pdf for the three. The
/// uniform part bounds the weight where the response stays positive as |cos θ| → 0 (the CDRF's
/// wrap, τ at the terminator); without it those grazing samples were fireflies on Figure 13's
/// grains. Zero weight: the path ends.
struct FastBounce {
  Vector3f direction;
  Color weight = Color::Zero();
};
FastBounce fast_rice_bounce(const PathContext& c, const ShadingPoint& hit, const Material& m, const Vector3f& n,
                            const Vector3f& wo, PathSampler& sampler) {
  constexpr double kSpecular = 0.1, kUniform = 0.1, kFront = 0.75 * (1.0 - kUniform);
  const auto [lobe, u] = sampler.pair();
  const auto [a, b] = sampler.pair();
  FastBounce next;
  if (lobe < kSpecular) {
    next.weight = sample_specular(m, n, wo, a, b, next.direction) / static_cast<float>(kSpecular);
    return next;
  }
  if (u < kUniform) next.direction = Environment::direction(a, b).cast<float>();
  else next.direction = cosine_direction(u < kUniform + kFront ? n : Vector3f(-n), a, b);
  const double cos_i = n.dot(next.direction);
  const double pdf = kUniform / (4.0 * std::numbers::pi) +
                     (cos_i > 0.0 ? kFront * cos_i : (1.0 - kUniform - kFront) * -cos_i) / std::numbers::pi;
  const Color f = diffuse_term(m, *c.settings.cdrf, n, wo, next.direction, hit.curvature, hit.thickness);
  next.weight = f / static_cast<float>((1.0 - kSpecular) * pdf);
  return next;
}

/// The suns' glints off a grain's surface, met from outside at p (normal n facing ω_o): the
/// material's GGX reflection lobe (material.hpp's specular_term, as the fast models have it),
/// each sun one sample and a shadow ray. Off the smooth dielectric the glint of a sun 0.27°
/// across is seen only by the rare reflected path that meets its disc: fireflies at 2× the
/// image's mean radiance in RMS at 512 samples, which hid every model's error (`rice study
/// render`).
Color sun_glints(const PathContext& c, const ShadingPoint& hit, const Material& m, const Medium& medium,
                 const Vector3f& n, const Vector3f& ng, const Vector3f& wo, PathSampler& sampler,
                 PathCounters& counters) {
  Color L = Color::Zero();
  for (const Sun::Sampler& sun : c.suns) {
    const auto [a, b] = sampler.pair();
    const LightSample l = sun.sample(a, b);
    const double f = specular_term(n, wo, l.direction, medium.refractive_index, m.roughness);
    if (!(f > 0.0)) continue;
    ++counters.rays;
    if (!c.scene.occluded(leaving(c.scene, hit.position, ng, l.direction))) L += l.weight * static_cast<float>(f);
  }
  return L;
}

/// A path on its way: the ray it follows next, what it has brought back and its throughput.
struct Path {
  Ray ray;
  Color radiance = Color::Zero(), throughput = Color::Constant(1.0f);
  // Whether a sun's disc, or a quad, met now is counted: after the camera and smooth events,
  // not after a diffuse bounce (whose shadow rays gathered them) nor, for suns, after a walk
  // that gathered them through the facets.
  bool sun_seen = true, quad_seen = true;
  int ignore = -1;  // the fast-rice grain the path just left, which it sees through
  /// Goes on from `hit` along `direction` after a bounce that gathered the lights itself.
  void bounce(const PathContext& c, const ShadingPoint& hit, const Vector3f& ng, const Vector3f& direction,
              const Color& weight) {
    throughput *= weight;
    sun_seen = quad_seen = false;
    ray = leaving(c.scene, hit.position, ng, direction);
  }
};

/// At a fast-rice point: its direct light, then a bounce into its response. False: the path ends.
bool fast_rice_event(const PathContext& c, const ShadingPoint& hit, const Material& m, Path& path,
                     PathSampler& sampler, PathCounters& counters) {
  const Vector3f ng = hit.geometric_normal, wo = -path.ray.direction;
  const Vector3f n = hit.shading_normal.dot(wo) > 0.0f ? hit.shading_normal : ng;
  path.radiance += path.throughput * fast_rice_direct(c, hit, m, n, ng, wo, sampler, counters);
  const FastBounce next = fast_rice_bounce(c, hit, m, n, wo, sampler);
  if (!(next.weight > 0.0f).any()) return false;
  path.bounce(c, hit, ng, next.direction, next.weight);
  path.ignore = hit.instance;
  return true;
}

/// At a grain's boundary met from outside: the suns' glints, then reflection off it or a walk
/// inside it by the Fresnel odds. False: the path ends.
bool grain_boundary_event(const PathContext& c, const ShadingPoint& hit, const Material& m, const Medium& medium,
                          Path& path, PathSampler& sampler, PathCounters& counters) {
  const Vector3f ng = hit.geometric_normal;
  const Vector3d d = path.ray.direction.cast<double>(), n = ng.cast<double>();
  const double cos_outside = -d.dot(n);
  const bool glints = c.settings.rough_sun_glints && !c.suns.empty();
  if (glints) {
    const Vector3f wo = -path.ray.direction, shading = hit.shading_normal.dot(wo) > 0.0f ? hit.shading_normal : ng;
    path.radiance += path.throughput * sun_glints(c, hit, m, medium, shading, ng, wo, sampler, counters);
  }
  const auto [a, unused] = sampler.pair();
  path.sun_seen = path.quad_seen = true;
  if (a < fresnel_reflectance(cos_outside, medium.refractive_index)) {
    path.ray = leaving(c.scene, hit.position, ng, (d + 2.0 * cos_outside * n).normalized().cast<float>());
    path.sun_seen = !glints;  // the suns' reflection is the glints' above
    return true;
  }
  const WalkExit out = walk(c, hit.instance, medium, hit.position, ng, refract(d, n, medium.refractive_index),
                            path.throughput, path.radiance, sampler, counters);
  if (!out.ray) return false;
  path.ray = *out.ray;
  path.sun_seen = !out.suns_gathered;
  return true;
}

/// At a metal point: its direct light through the lobe, then a bounce into the lobe. False:
/// the path ends (no sample, or one into the surface).
bool metal_event(const PathContext& c, const ShadingPoint& hit, const Material& m, Path& path, PathSampler& sampler,
                 PathCounters& counters) {
  const Vector3f ng = hit.geometric_normal, wo = -path.ray.direction;
  const Vector3f n = hit.shading_normal.dot(wo) > 0.0f ? hit.shading_normal : Vector3f(-hit.shading_normal);
  path.radiance += path.throughput * metal_direct(c, hit, m, n, ng, wo, sampler, counters);
  const auto [a, b] = sampler.pair();
  Vector3f next;
  const Color weight = sample_specular(m, n, wo, a, b, next);
  if (!(weight > 0.0f).any() || next.dot(ng) * wo.dot(ng) <= 0.0f) return false;
  path.bounce(c, hit, ng, next, weight);
  return true;
}

/// At a Lambertian point: its direct light, then a cosine-weighted bounce. False: the path ends.
bool lambertian_event(const PathContext& c, const ShadingPoint& hit, const Material& m, Path& path,
                      PathSampler& sampler, PathCounters& counters) {
  const Vector3f d = path.ray.direction, ng = hit.geometric_normal;
  const Vector3f n = hit.shading_normal.dot(d) < 0.0f ? hit.shading_normal : Vector3f(-hit.shading_normal);
  const Vector3f n_geometric = ng.dot(d) < 0.0f ? ng : Vector3f(-ng);
  path.radiance += path.throughput * direct_light(c, hit, n, m.albedo, sampler, counters);
  const auto [a, b] = sampler.pair();
  const Vector3f next = cosine_direction(n, a, b);
  if (next.dot(n_geometric) <= 0.0f) return false;  // under the geometric surface: no light comes that way
  path.bounce(c, hit, n_geometric, next, m.albedo);
  return true;
}

/// The radiance one path brings back along the camera ray.
Color trace(const PathContext& c, Ray ray, PathSampler& sampler, PathCounters& counters) {
  Path path{ray};
  ++counters.paths;
  for (int depth = 0;; ++depth) {
    ++counters.rays;
    const std::optional<ShadingPoint> hit = c.scene.intersect(path.ray, path.ignore);
    path.ignore = -1;
    if (path.quad_seen)
      path.radiance +=
          path.throughput * quad_light(c, path.ray, hit ? hit->t : std::numeric_limits<float>::infinity());
    if (!hit) {
      path.radiance += path.throughput * (c.lights.environment.radiance(path.ray.direction) +
                                          (path.sun_seen ? sun_discs(c, path.ray.direction) : Color::Zero()));
      break;
    }
    if (depth == c.settings.max_depth) break;  // the last ray was traced for the lights it meets
    const Medium* medium = medium_of(c, hit->material);
    const Material& material = c.materials[hit->material];
    const bool fast = fast_rice(c, material, medium);
    if ((medium || fast) && path.ray.direction.dot(hit->geometric_normal) > 0.0f) {
      // Leaving a grain the path was not walking in: it started inside an overlapping one.
      // Pass through.
      path.ray = leaving(c.scene, hit->position, hit->geometric_normal, path.ray.direction);
      continue;
    }
    const bool goes_on = fast     ? fast_rice_event(c, *hit, material, path, sampler, counters)
                         : medium ? grain_boundary_event(c, *hit, material, *medium, path, sampler, counters)
                         : material.kind == MaterialKind::kMetal
                             ? metal_event(c, *hit, material, path, sampler, counters)
                             : lambertian_event(c, *hit, material, path, sampler, counters);
    if (!goes_on) break;
    if (depth >= 3) {  // Russian roulette on the throughput
      const float keep = std::min(0.95f, path.throughput.maxCoeff());
      const auto [u, unused] = sampler.pair();
      if (u >= keep) break;
      path.throughput /= keep;
    }
  }
  return path.radiance;
}

void validate(const std::vector<Material>& materials, const std::vector<std::optional<Medium>>& media,
              const RenderScene& scene, const PathTraceSettings& s) {
  if (s.width < 1 || s.height < 1 || s.samples_per_pixel < 1 || s.max_depth < 1 || s.max_scatterings < 1)
    throw std::invalid_argument("path_trace: width, height, samples per pixel, depth and scatterings must be at least 1");
  check_instance_materials(scene, materials.size(), "path_trace");
  validate(s.adaptive, "path_trace");
  for (std::size_t k = 0; k < media.size(); ++k) {
    if (!media[k]) continue;
    const Medium& m = *media[k];
    if (!(m.scattering >= 0.0) || !(m.absorption >= 0.0) || !(m.scattering + m.absorption > 0.0) ||
        !(std::abs(m.anisotropy) < 1.0) || !(m.refractive_index > 0.0))
      throw std::invalid_argument("path_trace: medium of material " + std::to_string(k) +
                                  " needs scattering and absorption >= 0 with a positive sum, |anisotropy| < 1 and "
                                  "refractive index > 0");
  }
}

}  // namespace

Image path_trace(const RenderScene& scene, const std::vector<Material>& materials,
                 const std::vector<std::optional<Medium>>& media, const Lights& lights, const Camera& camera,
                 const PathTraceSettings& settings, PathTraceStats* stats,
                 const std::function<void(int, int)>& progress, const std::function<bool()>& cancelled) {
  validate(materials, media, scene, settings);
  const auto start = std::chrono::steady_clock::now();
  PathContext context{scene, materials, media, lights, {}, settings};
  for (const Sun& sun : lights.suns) context.suns.push_back(sun.sampler());
  const PixelWindow window = rendered_pixels(settings.width, settings.height, settings.crop, "path_trace");
  const Camera::Frame frame = camera.frame(static_cast<double>(settings.width) / settings.height);
  PathCounters totals;
  std::mutex totals_lock;
  // A tile's sampler: the pixel's paths first, ..., first + count - 1, and its counters.
  struct TileSampler {
    const PathContext& context;
    const Camera::Frame& frame;
    PathCounters& totals;
    std::mutex& totals_lock;
    PathCounters counters{};
    void operator()(int x, int y, int first, int count, PixelSums& sums) {
      const PathTraceSettings& s = context.settings;
      const PixelSampler pixel(s.sampler, s.seed, x, y, s.samples_per_pixel);
      for (int i = first; i < first + count; ++i) {
        double px = 0.0, py = 0.0, la = 0.0, lb = 0.0;
        pixel.pair(i, 0, px, py);
        pixel.pair(i, 1, la, lb);
        const CameraRay cr = frame.ray((x + px) / s.width, (y + py) / s.height, la, lb);
        PathSampler sampler{pixel, i};
        sums.add(trace(context, {cr.origin, cr.direction}, sampler, counters));
      }
    }
    void finish() {
      const std::lock_guard lock(totals_lock);
      totals += counters;
    }
  };
  const Image image = sample_pixels(settings.width, settings.height, window, settings.samples_per_pixel,
                                    settings.adaptive, progress, cancelled,
                                    [&] { return TileSampler{context, frame, totals, totals_lock}; });
  if (stats) {
    *stats = {totals.paths, totals.rays, totals.scatterings, totals.walks_cut, totals.walks_lost,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  }
  return image;
}

}  // namespace rice::shading
