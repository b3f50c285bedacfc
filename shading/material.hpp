// Surface materials of the renderer, as the product f(ω_o, ω_i)·cos-like term that multiplies
// incident radiance (so each is one function of the two directions):
//  - kRice: the CDRF diffuse term (paper eqs. 6–8), albedo/π · f_r(θ_i, σ0 max(κ, 0)), which
//    replaces the cosine of a Lambertian surface and lets light in past the terminator on
//    convex parts, plus the wet surface's dielectric specular lobe. With a translucency
//    table it is the translucent rice model (translucency.hpp, eq. T1): τ(d, cos θ_i)/π
//    more, for the light through a grain of thickness d, in the albedo's colour. The CDRF's σ = σ0/r is
//    derived for convex surfaces of radius r; in a concave pit light does not wrap around,
//    and with σ0 |κ| the pores of a shaded grain glowed at f_r ≈ 1/π;
//  - kDiffuse: Lambertian, albedo/π · max(cos θ_i, 0);
//  - kGlazed: Lambertian under a dielectric coat: the diffuse part weighted by the coat's
//    Fresnel transmittance, plus the coat's specular lobe (a glazed bowl);
//  - kSubsurfaceReference: rice whose diffuse radiance was baked by the random walk
//    (subsurface_bake.hpp) and is read at the hit, not computed from the lights here; the
//    same specular lobe as kRice;
//  - kMetal: a conductor, the specular lobe alone (metal absorbs what it does not reflect), its
//    Fresnel reflectance coloured, by Schlick's approximation from the albedo taken as the
//    reflectance at normal incidence F0 (brushed steel).
// The specular lobe is a GGX microfacet BRDF (Walter et al. 2007) with unpolarised Fresnel
// reflectance and the height-correlated Smith shadowing.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shading/cdrf.hpp"
#include "shading/fresnel.hpp"
#include "shading/lights.hpp"
#include "shading/tangent_frame.hpp"
#include "shading/translucency.hpp"

#include <memory>

namespace rice::shading {

enum class MaterialKind { kRice, kDiffuse, kGlazed, kSubsurfaceReference, kMetal };

struct Material {
  MaterialKind kind = MaterialKind::kDiffuse;
  Color albedo = Color::Constant(0.8f);  ///< kMetal: the reflectance at normal incidence F0
  double sigma0 = 0.0;          ///< [m], kRice: CDRF width σ = σ0 max(κ, 0)
  double refractive_index = 1.45;  ///< of the specular coat (kRice, kGlazed)
  double roughness = 0.15;      ///< GGX α of the specular lobe
  /// kRice: τ(d, cos θ) of the translucent model; null: the paper's CDRF alone.
  std::shared_ptr<const TranslucencyTable> translucency = nullptr;
};

/// GGX normal distribution D(h) for cos θ_h = n·h.
inline double ggx_distribution(double cos_h, double alpha) {
  const double a2 = alpha * alpha, c2 = cos_h * cos_h;
  const double d = c2 * (a2 - 1.0) + 1.0;
  return a2 / (std::numbers::pi * d * d);
}

/// Height-correlated Smith masking–shadowing G2 for GGX (Heitz 2014, eq. 99).
inline double ggx_smith(double cos_o, double cos_i, double alpha) {
  const double a2 = alpha * alpha;
  auto lambda = [&](double c) { return 0.5 * (-1.0 + std::sqrt(1.0 + a2 * (1.0 - c * c) / (c * c))); };
  return 1.0 / (1.0 + lambda(cos_o) + lambda(cos_i));
}

/// Schlick's approximation of a conductor's Fresnel reflectance, F0 + (1 − F0)(1 − cos θ)⁵
/// (Schlick 1994), for F0 its reflectance at normal incidence.
inline Color schlick_reflectance(const Color& f0, double cos_theta) {
  const float m = static_cast<float>(std::pow(1.0 - std::clamp(cos_theta, 0.0, 1.0), 5.0));
  return f0 + (Color::Constant(1.0f) - f0) * m;
}

/// The specular lobe's Fresnel reflectance at cos θ = ω_o·h: the conductor's coloured one
/// (kMetal) or the coat's dielectric one.
inline Color specular_fresnel(const Material& m, double o_dot_h) {
  if (m.kind == MaterialKind::kMetal) return schlick_reflectance(m.albedo, o_dot_h);
  return Color::Constant(static_cast<float>(fresnel_reflectance(o_dot_h, m.refractive_index)));
}

/// The GGX lobe without its Fresnel factor, D(h) G2 / (4 cos θ_o) (f_s cos θ_i = this · F), for
/// unit n, ω_o, ω_i; zero below the surface on either side. `o_dot_h`: ω_o·h, for F.
inline double ggx_reflection(const Eigen::Vector3f& n, const Eigen::Vector3f& wo, const Eigen::Vector3f& wi,
                             double alpha, double& o_dot_h) {
  const double cos_o = n.dot(wo), cos_i = n.dot(wi);
  if (cos_o <= 0.0 || cos_i <= 0.0) return 0.0;
  const Eigen::Vector3f h = (wo + wi).normalized();
  o_dot_h = wo.dot(h);
  return ggx_distribution(n.dot(h), alpha) * ggx_smith(cos_o, cos_i, alpha) / (4.0 * cos_o);
}

/// Specular lobe f_s · cos θ_i of a dielectric coat of index η.
inline double specular_term(const Eigen::Vector3f& n, const Eigen::Vector3f& wo, const Eigen::Vector3f& wi,
                            double eta, double alpha) {
  double o_dot_h = 0.0;
  const double lobe = ggx_reflection(n, wo, wi, alpha, o_dot_h);
  return lobe > 0.0 ? lobe * fresnel_reflectance(o_dot_h, eta) : 0.0;
}

/// The material's specular lobe f_s · cos θ_i, in its Fresnel colour.
inline Color specular_term(const Material& m, const Eigen::Vector3f& n, const Eigen::Vector3f& wo,
                           const Eigen::Vector3f& wi) {
  double o_dot_h = 0.0;
  const double lobe = ggx_reflection(n, wo, wi, m.roughness, o_dot_h);
  if (!(lobe > 0.0)) return Color::Zero();
  return specular_fresnel(m, o_dot_h) * static_cast<float>(lobe);
}

/// Diffuse part f_d · cos-like for light from ω_i at a point of curvature κ [1/m] and
/// thickness d [m].
inline Color diffuse_term(const Material& m, const CdrfTable& cdrf, const Eigen::Vector3f& n, const Eigen::Vector3f& wo,
                          const Eigen::Vector3f& wi, double curvature, double thickness = 0.0) {
  const double cos_i = n.dot(wi);
  switch (m.kind) {
    case MaterialKind::kRice: {
      double exitance = cdrf(cos_i, m.sigma0 * std::max(curvature, 0.0));  // over the albedo A
      if (m.translucency) exitance = std::max(0.0, exitance + (*m.translucency)(thickness, cos_i) / m.albedo.mean());
      return m.albedo * static_cast<float>(exitance / std::numbers::pi);
    }
    case MaterialKind::kDiffuse:
      return m.albedo * static_cast<float>(std::max(cos_i, 0.0) / std::numbers::pi);
    case MaterialKind::kSubsurfaceReference:
      return Color::Zero();  // baked: ShadingPoint::baked
    case MaterialKind::kMetal:
      return Color::Zero();
    case MaterialKind::kGlazed: {
      if (cos_i <= 0.0 || n.dot(wo) <= 0.0) return Color::Zero();
      const double through = (1.0 - fresnel_reflectance(cos_i, m.refractive_index)) *
                             (1.0 - fresnel_reflectance(n.dot(wo), m.refractive_index));
      return m.albedo * static_cast<float>(through * cos_i / std::numbers::pi);
    }
  }
  return Color::Zero();
}

inline bool has_specular(const Material& m) { return m.kind != MaterialKind::kDiffuse; }

/// f · cos-like, diffuse and specular together.
inline Color surface_response(const Material& m, const CdrfTable& cdrf, const Eigen::Vector3f& n,
                              const Eigen::Vector3f& wo, const Eigen::Vector3f& wi, double curvature,
                              double thickness = 0.0) {
  Color c = diffuse_term(m, cdrf, n, wo, wi, curvature, thickness);
  if (has_specular(m)) c += specular_term(m, n, wo, wi);
  return c;
}

/// A direction from the GGX lobe: a half vector h drawn with pdf D(h) cos θ_h, ω_o reflected
/// about it. Returns the weight f_s cos θ_i / pdf(ω_i) without the Fresnel factor, zero where
/// the reflection goes below; `o_dot_h`: ω_o·h, for F.
inline double sample_ggx_reflection(const Eigen::Vector3f& n, const Eigen::Vector3f& wo, double alpha, double a,
                                    double b, Eigen::Vector3f& wi, double& o_dot_h) {
  const double phi = 2.0 * std::numbers::pi * b;
  const double cos_h = std::sqrt((1.0 - a) / (1.0 + (alpha * alpha - 1.0) * a));
  const double sin_h = std::sqrt(std::max(0.0, 1.0 - cos_h * cos_h));
  const auto [t, s] = tangent_frame(n);
  const Eigen::Vector3f h =
      (static_cast<float>(cos_h) * n + static_cast<float>(sin_h) * (static_cast<float>(std::cos(phi)) * t + static_cast<float>(std::sin(phi)) * s)).normalized();
  o_dot_h = wo.dot(h);
  if (o_dot_h <= 0.0) return 0.0;
  wi = (2.0f * static_cast<float>(o_dot_h) * h - wo).normalized();
  const double cos_i = n.dot(wi), cos_o = n.dot(wo);
  if (cos_i <= 0.0 || cos_o <= 0.0) return 0.0;
  // f cos_i / pdf with pdf = D cos_h / (4 o·h): G2 (o·h) / (cos_o cos_h), F aside.
  return ggx_smith(cos_o, cos_i, alpha) * o_dot_h / (cos_o * cos_h);
}

/// A direction from the material's specular lobe and its weight f_s cos θ_i / pdf, in its
/// Fresnel colour.
inline Color sample_specular(const Material& m, const Eigen::Vector3f& n, const Eigen::Vector3f& wo, double a,
                             double b, Eigen::Vector3f& wi) {
  double o_dot_h = 0.0;
  const double weight = sample_ggx_reflection(n, wo, m.roughness, a, b, wi, o_dot_h);
  if (!(weight > 0.0)) return Color::Zero();
  return specular_fresnel(m, o_dot_h) * static_cast<float>(weight);
}

}  // namespace rice::shading
