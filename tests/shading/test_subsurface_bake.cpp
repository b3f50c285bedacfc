// The mesh bake of the subsurface reference (shading/subsurface_bake.hpp) against the
// analytic-sphere random walk (shading/random_walk.hpp) it generalises, and its determinism.
#include "shading/subsurface_bake.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>

#include "tests/shading/test_meshes.hpp"

namespace rice::shading {
namespace {

constexpr double kRadius = 1e-3;
const Medium kMedium{4000.0, 10.0, 0.0, 1.45};

struct Baked {
  std::unique_ptr<RenderScene> scene;
  std::vector<float> exitance;
  test_support::TestMesh mesh;
};

// A sphere of radius 1 mm (icosphere level 4) under a sun of irradiance 1 along +z.
Baked bake_sphere(long long photons, std::uint64_t seed) {
  Baked b{std::make_unique<RenderScene>(), {}, test_support::icosphere(4)};
  b.scene->add_instance(b.scene->add_prototype(b.mesh.V, b.mesh.F), Eigen::Affine3d(Eigen::Scaling(kRadius)), 0);
  b.scene->commit();
  Lights lights;
  lights.suns.push_back({.direction = {0, 0, 1}, .angular_radius = 0.0f, .irradiance = Color::Constant(1.0f)});
  b.exitance = bake_subsurface(*b.scene, {0}, {kMedium}, lights, {.photons_per_light = photons, .seed = seed})[0];
  return b;
}

// The bake's vertex exitance averaged in θ bands (area-weighted) against the analytic sphere.
TEST(SubsurfaceBake, SphereMeshMatchesTheAnalyticSphereWalk) {
  const Baked baked = bake_sphere(400'000, 1);
  const auto area = baked.scene->vertex_areas(0);
  const int bins = 12;
  std::vector<double> flux(bins, 0.0), band(bins, 0.0);
  for (Eigen::Index v = 0; v < baked.mesh.V.rows(); ++v) {
    const double theta = std::acos(std::clamp(baked.mesh.V(v, 2), -1.0, 1.0));
    const int k = std::min(bins - 1, static_cast<int>(theta / std::numbers::pi * bins));
    flux[k] += baked.exitance[v] * area[v];
    band[k] += area[v];
  }
  const ExitanceProfile sphere = sphere_exitance(kMedium, kRadius, {.photons = 400'000, .bins = bins});
  for (int k = 0; k < bins; ++k) {
    // Both are Monte Carlo (~1% each here); the mesh's facets sit up to 0.3% inside the sphere.
    EXPECT_NEAR(flux[k] / band[k], sphere.exitance[k], 0.03 * sphere.exitance[k] + 0.005) << "band " << k;
  }
}

TEST(SubsurfaceBake, SameSeedSameExitanceOnAnyThreadCount) {
  std::vector<float> one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = bake_sphere(40'000, 3).exitance;
  }
  EXPECT_EQ(one, bake_sphere(40'000, 3).exitance);
}

// The baked radiance M/π is what a kSubsurfaceReference material shows, from any side.
TEST(SubsurfaceBake, StoresRadianceForTheRenderer) {
  const Baked baked = bake_sphere(20'000, 5);
  const auto hit = baked.scene->intersect({{0, 0, 1.0f}, {0, 0, -1}});
  ASSERT_TRUE(hit.has_value());
  const Eigen::Vector3i tri = baked.scene->triangle(0, hit->primitive);
  double expected = 0.0;
  for (int k = 0; k < 3; ++k) expected += hit->barycentric[k] * baked.exitance[tri[k]] / std::numbers::pi;
  EXPECT_NEAR(hit->baked, expected, 1e-6 * expected);
  EXPECT_GT(hit->baked, 0.0);
}

// Flux that leaves the outer surface, Σ M A over its vertices, of a mesh whose first `outer`
// vertices are the outer surface, under a sun of irradiance 1 along +z.
double outer_flux(const test_support::TestMesh& mesh, Eigen::Index outer, std::vector<float>* pore_exitance) {
  RenderScene scene;
  scene.add_instance(scene.add_prototype(mesh.V, mesh.F), Eigen::Affine3d::Identity(), 0);
  scene.commit();
  Lights lights;
  lights.suns.push_back({.direction = {0, 0, 1}, .angular_radius = 0.0f, .irradiance = Color::Constant(1.0f)});
  const std::vector<float> m = bake_subsurface(scene, {0}, {kMedium}, lights, {.photons_per_light = 100'000, .seed = 2})[0];
  const std::vector<double> area = scene.vertex_areas(0);
  double flux = 0.0;
  for (Eigen::Index v = 0; v < outer; ++v) flux += m[v] * area[v];
  if (pore_exitance) pore_exitance->assign(m.begin() + outer, m.end());
  return flux;
}

// Light that leaves into a pore inside the grain goes back in across it; it leaves through
// the outer surface, nearly all of it (little absorption here), as from a solid sphere.
// Tallied where it first left, it lit the pore's walls, which no one sees, and the outer
// surface lost 40% of its light.
TEST(SubsurfaceBake, LightThatLeavesIntoAPoreGoesBackIn) {
  const test_support::TestMesh solid = test_support::icosphere(3);
  const test_support::TestMesh hollow = test_support::hollow_sphere(3, kRadius, 0.6 * kRadius);
  std::vector<float> pore;
  const double through_pore = outer_flux(hollow, solid.V.rows(), &pore);
  const double solid_flux = outer_flux({kRadius * solid.V, solid.F}, solid.V.rows(), nullptr);
  EXPECT_NEAR(through_pore / solid_flux, 1.0, 0.03);
  for (const float m : pore) EXPECT_EQ(m, 0.0f);
}

}  // namespace
}  // namespace rice::shading
