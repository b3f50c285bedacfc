// The renderer (shading/renderer.hpp) against known answers: a diffuse sphere in a uniform
// environment, a plane under the sun, the CDRF on a sphere; shadows, the rice grain's own
// shadow ignored, instancing, determinism, and the samplers' convergence.
#include "shading/renderer.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "tests/shading/test_meshes.hpp"

namespace rice::shading {
namespace {

const CdrfTable& table() {
  static const CdrfTable t(129, 129);
  return t;
}

// Two triangles: the square [−h, h]² at height z, facing +z.
test_support::TestMesh square(double h, double z) {
  test_support::TestMesh m{MeshVertices(4, 3), MeshTriangles(2, 3)};
  m.V << -h, -h, z, h, -h, z, h, h, z, -h, h, z;
  m.F << 0, 1, 2, 0, 2, 3;
  return m;
}

// Adds `mesh` as its own prototype, placed where it is, with `material`.
void place(RenderScene& scene, const test_support::TestMesh& mesh, int material = 0) {
  scene.add_instance(scene.add_prototype(mesh.V, mesh.F), Eigen::Affine3d::Identity(), material);
}

// A closed convex diffuse object in a uniform environment of radiance 1 reflects its albedo
// (pbrt's furnace-style known answer), with ambient occlusion on: nothing occludes it.
TEST(Renderer, DiffuseSphereInAUniformEnvironmentReflectsItsAlbedo) {
  RenderScene scene;
  const auto sphere = test_support::icosphere(5);
  place(scene, sphere);
  scene.commit();
  Lights lights;
  lights.environment.constant = Color::Constant(1.0f);
  const std::vector<Material> materials = {{.kind = MaterialKind::kDiffuse, .albedo = Color::Constant(0.5f)}};
  const Image image = render(scene, materials, lights, test_support::looking_down(4.0, 40.0), table(),
                             {.width = 24, .height = 24, .samples_per_pixel = 256});
  // The centre pixels see the sphere; the corners see the environment.
  double centre = 0.0;
  for (int y = 10; y < 14; ++y)
    for (int x = 10; x < 14; ++x) centre += image.at(x, y).mean() / 16.0;
  EXPECT_NEAR(centre, 0.5, 0.01);
  EXPECT_FLOAT_EQ(image.at(0, 0).mean(), 1.0f);
}

// A Lambertian plane under a sun of irradiance π at 60° from the zenith: L = ρ cos 60°.
TEST(Renderer, LambertianPlaneUnderTheSun) {
  RenderScene scene;
  const auto ground = square(1.0, 0.0);
  place(scene, ground);
  scene.commit();
  Lights lights;
  lights.suns.push_back({.direction = {std::sin(1.0472f), 0.0f, std::cos(1.0472f)},
                         .irradiance = Color::Constant(std::numbers::pi_v<float>)});
  const std::vector<Material> materials = {{.kind = MaterialKind::kDiffuse, .albedo = Color(0.2f, 0.4f, 0.8f)}};
  const Image image = render(scene, materials, lights, test_support::looking_down(1.0, 30.0), table(),
                             {.width = 8, .height = 8, .samples_per_pixel = 64});
  // cos θ varies by ±0.4% over the sun's disc; 64 samples average that down.
  for (const auto& p : image.pixels) {
    EXPECT_NEAR(p[0], 0.1, 1e-4);
    EXPECT_NEAR(p[2], 0.4, 4e-4);
  }
}

// A rice sphere under the sun: each visible point shows albedo/π · f_r(θ, σ0/r) · E, also past
// the terminator (its own shadow is ignored), where a diffuse sphere is black.
TEST(Renderer, RiceSphereFollowsTheCdrfPastTheTerminator) {
  const double radius = 2e-3, sigma0 = 1e-3;  // σ = 0.5
  RenderScene scene;
  const auto sphere = test_support::icosphere(5);
  const Eigen::VectorXd kappa = Eigen::VectorXd::Constant(sphere.V.rows(), 1.0);  // unit sphere: κ = 1
  scene.add_instance(scene.add_prototype(sphere.V, sphere.F, kappa), Eigen::Affine3d(Eigen::Scaling(radius)), 0);
  scene.commit();
  Lights lights;
  lights.suns.push_back({.direction = {1.0f, 0.0f, 0.0f}, .irradiance = Color::Constant(std::numbers::pi_v<float>)});
  const std::vector<Material> materials = {
      {.kind = MaterialKind::kRice, .albedo = Color::Constant(1.0f), .sigma0 = sigma0, .roughness = 1.0}};
  const Camera camera = test_support::looking_down(50 * radius, 3.0);
  const RenderSettings settings{.width = 32, .height = 32, .samples_per_pixel = 16};
  const Image image = render(scene, materials, lights, camera, table(), settings);
  int checked = 0, past_terminator = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const CameraRay r = camera.ray((x + 0.5) / 32, (y + 0.5) / 32, 0, 0, 1.0);
      const auto hit = scene.intersect({r.origin, r.direction});
      if (!hit || hit->shading_normal.z() < 0.5f) continue;  // off the sphere or near its rim
      const double cos_theta = hit->shading_normal.x();
      // The matte specular (α = 1, Fresnel ~3%) adds a little; the CDRF term dominates.
      const double expected = table()(cos_theta, sigma0 / radius);
      EXPECT_NEAR(image.at(x, y).mean(), expected, 0.03 + 0.1 * expected) << x << " " << y;
      ++checked;
      if (cos_theta < -0.1) {
        EXPECT_GT(image.at(x, y).mean(), 0.0f);
        ++past_terminator;
      }
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(past_terminator, 10);
}

TEST(Renderer, ShadowsAreASwitch) {
  RenderScene scene;
  const auto ground = square(1.0, 0.0), blocker = square(0.2, 0.5);
  place(scene, ground);
  place(scene, blocker);
  scene.commit();
  Lights lights;
  lights.suns.push_back({.direction = {0.0f, 0.0f, 1.0f}, .irradiance = Color::Constant(1.0f)});
  const std::vector<Material> materials = {{.kind = MaterialKind::kDiffuse}};
  const Camera camera = test_support::looking_down(0.4, 60.0);  // between the ground and the blocker above it
  RenderSettings settings{.width = 9, .height = 9, .samples_per_pixel = 1};
  const Image shadowed = render(scene, materials, lights, camera, table(), settings);
  settings.shadows = false;
  const Image lit = render(scene, materials, lights, camera, table(), settings);
  EXPECT_EQ(shadowed.at(4, 4).mean(), 0.0f);
  EXPECT_GT(lit.at(4, 4).mean(), 0.2f);
}

TEST(Renderer, SameSeedSameImageOnAnyThreadCount) {
  RenderScene scene;
  const auto sphere = test_support::icosphere(3);
  place(scene, sphere);
  scene.commit();
  Lights lights;
  lights.environment.constant = Color::Constant(1.0f);
  lights.quads.push_back({});
  const std::vector<Material> materials = {{.kind = MaterialKind::kGlazed}};
  const RenderSettings settings{.width = 40, .height = 30, .samples_per_pixel = 8, .seed = 3};
  Image one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = render(scene, materials, lights, test_support::looking_down(4.0, 30.0), table(), settings);
  }
  const Image many = render(scene, materials, lights, test_support::looking_down(4.0, 30.0), table(), settings);
  EXPECT_EQ(rms_difference(one, many), 0.0);
}

/// The pixels [x0, x0 + crop.width) × [y0, …) of `whole`.
Image pixels_of(const Image& whole, const PixelWindow& crop) {
  Image part(crop.width(), crop.height());
  for (int y = crop.y0; y < crop.y1; ++y)
    for (int x = crop.x0; x < crop.x1; ++x) part.at(x - crop.x0, y - crop.y0) = whole.at(x, y);
  return part;
}

// A crop window renders the very pixels the whole frame has there (a frame split across
// processes joins into the frame), and one outside the frame is refused.
TEST(Renderer, ACropIsThoseVeryPixelsOfTheWholeFrame) {
  RenderScene scene;
  const auto sphere = test_support::icosphere(3);
  place(scene, sphere);
  scene.commit();
  Lights lights;
  lights.environment.constant = Color::Constant(1.0f);
  lights.suns.push_back({});
  const std::vector<Material> materials = {{.kind = MaterialKind::kRice, .sigma0 = 0.3}};
  RenderSettings settings{.width = 40, .height = 30, .samples_per_pixel = 4, .seed = 3};
  const Camera camera = test_support::looking_down(4.0, 30.0);
  const Image whole = render(scene, materials, lights, camera, table(), settings);
  settings.crop = {5, 7, 29, 30};
  const Image crop = render(scene, materials, lights, camera, table(), settings);
  ASSERT_EQ(crop.width, 24);
  ASSERT_EQ(crop.height, 23);
  EXPECT_EQ(rms_difference(crop, pixels_of(whole, settings.crop)), 0.0);
  EXPECT_GT(mean_radiance(crop), 0.0);
  settings.crop = {30, 0, 41, 30};
  EXPECT_THROW(render(scene, materials, lights, camera, table(), settings), std::invalid_argument);
}

TEST(Renderer, InstancesMoveAndScaleTheirPrototype) {
  RenderScene scene;
  const auto sphere = test_support::icosphere(3);
  const int p = scene.add_prototype(sphere.V, sphere.F, Eigen::VectorXd::Constant(sphere.V.rows(), 1.0));
  Eigen::Affine3d moved = Eigen::Translation3d(5, 0, 0) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::Scaling(2.0);
  scene.add_instance(p, moved, 0);
  EXPECT_THROW(scene.add_instance(p, Eigen::Affine3d(Eigen::Scaling(1.0, 2.0, 1.0)), 0), std::invalid_argument);
  scene.commit();
  const auto hit = scene.intersect({{5, 0, 10}, {0, 0, -1}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->position.z(), 2.0, 0.02);
  EXPECT_NEAR(hit->curvature, 0.5, 1e-6);  // κ = 1 on the unit prototype, scaled by 2
  EXPECT_GT(hit->shading_normal.z(), 0.99f);
  EXPECT_FALSE(scene.intersect({{0, 0, 10}, {0, 0, -1}}).has_value());
  EXPECT_TRUE(scene.occluded({{5, 0, 10}, {0, 0, -1}}));
  EXPECT_FALSE(scene.occluded({{5, 0, 10}, {0, 0, -1}}, 0));  // the only instance, ignored
}

TEST(Renderer, RefusesBadSettingsAndMaterials) {
  RenderScene scene;
  const auto sphere = test_support::icosphere(1);
  place(scene, sphere, 3);
  scene.commit();
  const std::vector<Material> materials(1);
  EXPECT_THROW(render(scene, materials, {}, {}, table(), {.width = 0}), std::invalid_argument);
  EXPECT_THROW(render(scene, materials, {}, {}, table(), {.width = 4, .height = 4}), std::invalid_argument);
  EXPECT_THROW(scene.add_prototype(sphere.V, sphere.F), std::logic_error);  // after commit
}

// Stratified and Sobol samples beat independent ones on a soft shadow at equal sample counts.
TEST(Renderer, StratifiedAndSobolConvergeFasterThanIndependent) {
  RenderScene scene;
  const auto ground = square(1.0, 0.0), blocker = square(0.1, 0.2);
  place(scene, ground);
  place(scene, blocker);
  scene.commit();
  Lights lights;
  lights.quads.push_back({.corner = {-0.2f, -0.2f, 0.6f}, .edge_u = {0.4f, 0, 0}, .edge_v = {0, 0.4f, 0}});
  const std::vector<Material> materials = {{.kind = MaterialKind::kDiffuse}};
  const Camera camera = test_support::looking_down(0.15, 90.0);
  RenderSettings settings{.width = 24, .height = 24, .samples_per_pixel = 4096, .sampler = SamplerKind::kIndependent};
  const Image reference = render(scene, materials, lights, camera, table(), settings);
  settings.samples_per_pixel = 64;
  const double independent = rms_difference(render(scene, materials, lights, camera, table(), settings), reference);
  settings.sampler = SamplerKind::kStratified;
  const double stratified = rms_difference(render(scene, materials, lights, camera, table(), settings), reference);
  settings.sampler = SamplerKind::kSobol;
  const double sobol = rms_difference(render(scene, materials, lights, camera, table(), settings), reference);
  EXPECT_LT(stratified, 0.8 * independent);
  EXPECT_LT(sobol, 0.8 * independent);
}

TEST(Sampler, StratifiedFillsEveryStratumAndSobolIsA02Net) {
  for (int pixel = 0; pixel < 4; ++pixel) {
    const PixelSampler stratified(SamplerKind::kStratified, 9, pixel, 0, 16);
    std::vector<int> count(16, 0);
    for (int i = 0; i < 16; ++i) {
      double a, b;
      stratified.pair(i, 3, a, b);
      ++count[static_cast<int>(a * 4) + 4 * static_cast<int>(b * 4)];
    }
    for (int c : count) EXPECT_EQ(c, 1);
    // 64 Sobol points: every elementary box of area 1/64 (2^i × 2^(6−i) cells) holds one.
    const PixelSampler sobol(SamplerKind::kSobol, 9, pixel, 0, 64);
    for (int i = 0; i <= 6; ++i) {
      std::vector<int> boxes(64, 0);
      for (int k = 0; k < 64; ++k) {
        double a, b;
        sobol.pair(k, 5, a, b);
        ASSERT_GE(a, 0.0);
        ASSERT_LT(b, 1.0);
        ++boxes[static_cast<int>(a * (1 << i)) + (1 << i) * static_cast<int>(b * (1 << (6 - i)))];
      }
      for (int c : boxes) EXPECT_EQ(c, 1) << "boxes 2^" << i << " x 2^" << 6 - i;
    }
  }
}

TEST(Camera, CentreRayHitsTheTargetAndTheThinLensFocuses) {
  Camera c;
  c.position = {1, 2, 3};
  c.target = {0, 0, 0};
  const CameraRay centre = c.ray(0.5, 0.5, 0, 0, 1.5);
  EXPECT_NEAR((centre.direction - (-c.position.cast<float>()).normalized()).norm(), 0.0, 1e-6);
  c.aperture_radius = 0.1;
  c.focus_distance = 2.0;
  for (double a : {0.1, 0.9}) {
    const CameraRay r = c.ray(0.3, 0.6, a, 0.3, 1.5);
    const CameraRay pin = Camera{c.position, c.target, c.up, c.vertical_fov_degrees}.ray(0.3, 0.6, 0, 0, 1.5);
    // Both reach the same point on the plane of focus.
    const Eigen::Vector3f forward = (c.target - c.position).normalized().cast<float>();
    const Eigen::Vector3f p = r.origin + r.direction * ((c.position.cast<float>() + 2.0f * forward - r.origin).dot(forward) / r.direction.dot(forward));
    const Eigen::Vector3f q = pin.origin + pin.direction * (2.0f / pin.direction.dot(forward));
    EXPECT_LT((p - q).norm(), 1e-5);
  }
}

}  // namespace
}  // namespace rice::shading
