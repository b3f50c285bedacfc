// The studio's lights (experiments/render/studio_lighting.hpp) against the irradiance they are
// set to: the key gives key_irradiance at the subject's centre on a surface facing it, the
// fill fill_ratio of it, both from the camera's side of the subject; the set adds a table and
// a backdrop.
#include "experiments/render/studio_lighting.hpp"

#include <gtest/gtest.h>

namespace rice::experiments {
namespace {

/// Irradiance (red) at `p` on a surface facing the quad's centre, by 400² stratified samples.
double irradiance_facing(const shading::QuadLight& quad, const Eigen::Vector3f& p) {
  const Eigen::Vector3f centre = quad.corner + 0.5f * (quad.edge_u + quad.edge_v);
  const Eigen::Vector3f n = (centre - p).normalized();
  constexpr int kSide = 400;
  double sum = 0.0;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      const shading::LightSample s = quad.sample(p, (i + 0.5) / kSide, (j + 0.5) / kSide);
      sum += s.weight[0] * std::max(0.0f, n.dot(s.direction));
    }
  return sum / (kSide * kSide);
}

TEST(StudioLighting, TheKeyAndTheFillGiveTheIrradianceTheyAreSetTo) {
  const Eigen::AlignedBox3d subject(Eigen::Vector3d(-0.03, -0.03, 0.0), Eigen::Vector3d(0.03, 0.03, 0.04));
  const Eigen::Vector3d eye(0.2, -0.3, 0.2);
  const StudioLighting lighting{.key_irradiance = 3.0, .fill_ratio = 0.25};
  const shading::Lights lights = studio_lights(subject, eye, lighting);
  ASSERT_EQ(lights.quads.size(), 2u);
  const Eigen::Vector3f c = subject.center().cast<float>();
  EXPECT_NEAR(irradiance_facing(lights.quads[0], c), 3.0, 0.01);
  EXPECT_NEAR(irradiance_facing(lights.quads[1], c), 0.75, 0.0025);
  for (const shading::QuadLight& quad : lights.quads) {  // lit from the camera's side, from above
    const Eigen::Vector3d at = (quad.corner + 0.5f * (quad.edge_u + quad.edge_v)).cast<double>();
    EXPECT_GT((at - subject.center()).dot(eye - subject.center()), 0.0);
    EXPECT_GT(at.z(), subject.max().z());
  }
  shading::RenderScene scene;
  add_studio_set(scene, subject, eye, 3, 4);
  EXPECT_EQ(scene.instance_count(), 2);  // the table and the backdrop
}

}  // namespace
}  // namespace rice::experiments
