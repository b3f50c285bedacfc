// Adaptive sampling (shading/adaptive_sampling.hpp) in both integrators: a pixel's standard
// error; a pixel that never stops early is the fixed render's, bit for bit; flat pixels stop at
// the pilot's count; the image is the same on any thread count and a crop is the frame's very
// pixels; and at equal samples it beats the fixed count where the noise is uneven.
#include "shading/adaptive_sampling.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <stdexcept>

#include "shading/path_tracer.hpp"
#include "shading/renderer.hpp"
#include "tests/shading/test_meshes.hpp"

namespace rice::shading {
namespace {

const CdrfTable& adaptive_table() {
  static const CdrfTable t(129, 129);
  return t;
}

/// A diffuse ground square [−g, g]² under a blocker [−b, b]² and a square area light: a soft
/// shadow in the middle of the view, flat sky (radiance 0.5) around the ground.
struct SoftShadowScene {
  RenderScene scene;
  Lights lights;
  std::vector<Material> materials{{.kind = MaterialKind::kDiffuse}};
  Camera camera = test_support::looking_down(0.3, 90.0);
  explicit SoftShadowScene(double ground = 0.12, double blocker = 0.03) {
    for (const auto& [half, z] : {std::pair{ground, 0.0}, std::pair{blocker, 0.1}}) {
      test_support::TestMesh m{MeshVertices(4, 3), MeshTriangles(2, 3)};
      m.V << -half, -half, z, half, -half, z, half, half, z, -half, half, z;
      m.F << 0, 1, 2, 0, 2, 3;
      scene.add_instance(scene.add_prototype(m.V, m.F), Eigen::Affine3d::Identity(), 0);
    }
    scene.commit();
    lights.quads.push_back({.corner = {-0.1f, -0.1f, 0.4f}, .edge_u = {0.2f, 0, 0}, .edge_v = {0, 0.2f, 0}});
    lights.environment.constant = Color::Constant(0.5f);
  }
  Image render(const RenderSettings& s, RenderStats* stats = nullptr) const {
    return shading::render(scene, materials, lights, camera, adaptive_table(), s, stats);
  }
};

int pixels(const RenderSettings& s) { return s.width * s.height; }
int pilot_pixels(const RenderSettings& s) { return ((s.width + 7) / 8) * ((s.height + 7) / 8); }

TEST(PixelSums, StandardErrorIsTheSampleDeviationOverRootN) {
  PixelSums sums;
  EXPECT_TRUE(std::isinf(sums.standard_error()));
  for (const float v : {1.0f, 2.0f, 3.0f, 4.0f}) sums.add(Eigen::Array3f(v, v, v));
  // s² = Σ(v − 2.5)² / 3 = 5/3; s/√n = √(5/12)
  EXPECT_NEAR(sums.standard_error(), std::sqrt(5.0 / 12.0), 1e-12);
  EXPECT_FLOAT_EQ(sums.mean()[0], 2.5f);
  sums = {};
  for (int k = 0; k < 8; ++k) sums.add(Eigen::Array3f(0.3f, 0.6f, 0.9f));
  EXPECT_NEAR(sums.standard_error(), 0.0, 1e-9);
}

TEST(AdaptiveSampling, RefusesAnErrorOutsideZeroToOneAndAPilotOfOneSample) {
  const SoftShadowScene s;
  RenderSettings settings{.width = 8, .height = 8, .samples_per_pixel = 16};
  for (const AdaptiveSampling bad : {AdaptiveSampling{.relative_error = -0.1}, AdaptiveSampling{.relative_error = 1.0},
                                     AdaptiveSampling{.relative_error = 0.1, .min_samples = 1}}) {
    settings.adaptive = bad;
    EXPECT_THROW(s.render(settings), std::invalid_argument);
  }
  settings.adaptive = {.relative_error = 0.0, .min_samples = 1};  // off: the pilot is unused
  EXPECT_NO_THROW(s.render(settings));
}

TEST(AdaptiveSampling, APixelThatNeverStopsIsTheFixedRendersPixel) {
  // Ground in every pixel, lit by the area light's samples: no pixel's samples are all equal,
  // so none meets a target of 1e-12 of the mean (a flat pixel would: its error is 0).
  const SoftShadowScene s(10.0, 1e-5);
  RenderSettings fixed{.width = 24, .height = 16, .samples_per_pixel = 64, .seed = 5};
  RenderSettings adaptive = fixed;
  adaptive.adaptive = {.relative_error = 1e-12, .min_samples = 4};
  RenderStats stats;
  EXPECT_EQ(rms_difference(s.render(adaptive, &stats), s.render(fixed)), 0.0);
  EXPECT_EQ(stats.camera_rays, static_cast<long long>(pixels(fixed)) * 64 + pilot_pixels(fixed) * 4);
  // the path tracer too
  const PathTraceSettings path{.width = 24, .height = 16, .samples_per_pixel = 32, .seed = 5, .max_depth = 2};
  PathTraceSettings path_adaptive = path;
  path_adaptive.adaptive = adaptive.adaptive;
  const std::vector<std::optional<Medium>> media;
  EXPECT_EQ(rms_difference(path_trace(s.scene, s.materials, media, s.lights, s.camera, path_adaptive),
                           path_trace(s.scene, s.materials, media, s.lights, s.camera, path)),
            0.0);
}

TEST(AdaptiveSampling, FlatPixelsStopAtThePilotsCountAndNoisyOnesGoOn) {
  RenderSettings settings{.width = 24, .height = 16, .samples_per_pixel = 256, .seed = 5};
  settings.adaptive = {.relative_error = 0.01, .min_samples = 8};
  const long long pilot = pilot_pixels(settings) * 8;
  RenderStats sky, shadow;
  SoftShadowScene(1e-5, 1e-5).render(settings, &sky);  // specks: every pixel but one at most sees the sky
  EXPECT_LE(sky.camera_rays, pilot + (pixels(settings) - 1) * 8 + 256);
  SoftShadowScene().render(settings, &shadow);
  EXPECT_GT(shadow.camera_rays, pilot + 4LL * pixels(settings) * 8);
  EXPECT_LT(shadow.camera_rays, pilot + static_cast<long long>(pixels(settings)) * 256);
}

TEST(AdaptiveSampling, SameImageOnAnyThreadCountAndACropIsTheFramesPixels) {
  const SoftShadowScene s;
  RenderSettings settings{.width = 40, .height = 24, .samples_per_pixel = 128, .seed = 3};
  settings.adaptive = {.relative_error = 0.02, .min_samples = 8};
  Image one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = s.render(settings);
  }
  const Image many = s.render(settings);
  EXPECT_EQ(rms_difference(one, many), 0.0);
  settings.crop = {5, 7, 29, 24};
  const Image crop = s.render(settings);
  Image frame_part(crop.width, crop.height);
  for (int y = 7; y < 24; ++y)
    for (int x = 5; x < 29; ++x) frame_part.at(x - 5, y - 7) = many.at(x, y);
  EXPECT_EQ(rms_difference(crop, frame_part), 0.0);
}

TEST(AdaptiveSampling, BeatsTheFixedCountAtEqualSamplesWhereTheNoiseIsUneven) {
  // The soft shadow under the blocker is noisy, the sky flat: samples spent on the shadow
  // lower the image's error more than the same samples spread evenly.
  const SoftShadowScene s;
  RenderSettings settings{.width = 32, .height = 32, .samples_per_pixel = 4096, .seed = 11};
  const Image reference = s.render(settings);
  settings.seed = 1;
  settings.samples_per_pixel = 512;
  settings.adaptive = {.relative_error = 0.01, .min_samples = 8};
  RenderStats stats;
  const double adaptive = rms_difference(s.render(settings, &stats), reference);
  const double mean_samples = static_cast<double>(stats.camera_rays) / pixels(settings);
  settings.adaptive = {};
  settings.samples_per_pixel = static_cast<int>(std::ceil(mean_samples));
  const double fixed = rms_difference(s.render(settings), reference);
  EXPECT_LT(mean_samples, 256.0);
  EXPECT_LT(adaptive, 0.8 * fixed) << "adaptive at a mean of " << mean_samples << " samples";
}

}  // namespace
}  // namespace rice::shading
