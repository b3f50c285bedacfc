// The specular lobe of shading/material.hpp, on the metal that has nothing else: Schlick's
// Fresnel at its ends, the lobe's reciprocity, the sampled weight against the lobe over its
// pdf, and the energy it keeps (at most what comes in; nearly all at low roughness, GGX's
// single scattering losing some).
#include "shading/material.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rice::shading {
namespace {

const Eigen::Vector3f kUp(0.0f, 0.0f, 1.0f);

Material metal(float f0, double roughness) {
  return {.kind = MaterialKind::kMetal, .albedo = Color::Constant(f0), .roughness = roughness};
}

Eigen::Vector3f at_angle(double theta, double phi) {
  return Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta))
      .cast<float>();
}

TEST(Metal, SchlickIsF0HeadOnAndOneAtGrazingInEachChannel) {
  const Color f0(0.56f, 0.57f, 0.58f);
  EXPECT_TRUE(schlick_reflectance(f0, 1.0).isApprox(f0));
  EXPECT_TRUE(schlick_reflectance(f0, 0.0).isApprox(Color::Constant(1.0f)));
  const Color mid = schlick_reflectance(f0, 0.5);
  EXPECT_TRUE((mid > f0).all() && (mid < 1.0f).all());
}

TEST(Metal, HasNoDiffusePartAndItsLobeIsReciprocal) {
  const Material m = metal(0.6f, 0.25);
  const CdrfTable cdrf(17, 17);
  for (const double theta_o : {0.1, 0.7, 1.2})
    for (const double theta_i : {0.3, 0.9, 1.4}) {
      const Eigen::Vector3f wo = at_angle(theta_o, 0.4), wi = at_angle(theta_i, 2.9);
      EXPECT_TRUE(diffuse_term(m, cdrf, kUp, wo, wi, 0.0).isZero());
      // f(ω_o, ω_i) = f(ω_i, ω_o), and specular_term is f cos θ_i.
      const Color forth = specular_term(m, kUp, wo, wi) / static_cast<float>(std::cos(theta_i));
      const Color back = specular_term(m, kUp, wi, wo) / static_cast<float>(std::cos(theta_o));
      EXPECT_TRUE(forth.isApprox(back, 1e-4f)) << forth.transpose() << " against " << back.transpose();
    }
}

// The weight sample_specular returns is f cos θ_i / pdf with pdf = D(h) cos θ_h / (4 ω_o·h).
TEST(Metal, TheSampledWeightIsTheLobeOverItsPdf) {
  const Material m = metal(0.56f, 0.25);
  const Eigen::Vector3f wo = at_angle(0.6, 1.0);
  int checked = 0;
  for (int i = 1; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      Eigen::Vector3f wi;
      const Color weight = sample_specular(m, kUp, wo, i / 10.0, j / 10.0, wi);
      if (!(weight > 0.0f).any()) continue;
      const Eigen::Vector3f h = (wo + wi).normalized();
      const double pdf = ggx_distribution(h.z(), m.roughness) * h.z() / (4.0 * wo.dot(h));
      const Color expected = specular_term(m, kUp, wo, wi) / static_cast<float>(pdf);
      EXPECT_TRUE(weight.isApprox(expected, 1e-3f)) << weight.transpose() << " against " << expected.transpose();
      ++checked;
    }
  EXPECT_GT(checked, 80);
}

// A white metal (F0 = 1) sends back at most the light it gets, and at α = 0.25 seen head on
// most of it: a microfacet model of single scattering loses the light that would reflect again
// between the facets (8.6% here); the lobe's quadrature over the hemisphere agrees with its
// samples' mean.
TEST(Metal, AWhiteMetalKeepsAtMostTheLightAndMostOfItAtLowRoughness) {
  const Material m = metal(1.0f, 0.25);
  const Eigen::Vector3f wo = at_angle(0.2, 0.0);
  const int n = 400;
  double sampled = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Eigen::Vector3f wi;
      sampled += sample_specular(m, kUp, wo, (i + 0.5) / n, (j + 0.5) / n, wi).mean() / (n * n);
    }
  // ∫ f cos dω over the hemisphere by the midpoint rule in (cos θ, φ).
  double quadrature = 0.0;
  const int m_cos = 2000, m_phi = 400;
  for (int i = 0; i < m_cos; ++i)
    for (int j = 0; j < m_phi; ++j) {
      const double theta = std::acos((i + 0.5) / m_cos), phi = 2.0 * std::numbers::pi * (j + 0.5) / m_phi;
      quadrature += specular_term(m, kUp, wo, at_angle(theta, phi)).mean() * 2.0 * std::numbers::pi / (m_cos * m_phi);
    }
  EXPECT_LE(sampled, 1.0);
  EXPECT_GT(sampled, 0.9);
  EXPECT_NEAR(quadrature, sampled, 0.01);
}

}  // namespace
}  // namespace rice::shading
