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

}  // namespace
}  // namespace rice::shading
