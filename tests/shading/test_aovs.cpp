// The AOV pass (shading/aovs.hpp) against known answers: a labelled sphere seen from above
// has, at the centre pixel, a normal towards the camera, the depth of its top, its material's
// albedo and its label; the background has none; a crop holds the whole frame's values there.
#include "shading/aovs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/shading/test_meshes.hpp"

namespace rice::shading {
namespace {

TEST(Aovs, ASphereFromAboveHasItsNormalDepthAlbedoAndLabel) {
  RenderScene scene;
  const auto sphere = test_support::icosphere(5);
  scene.add_instance(scene.add_prototype(sphere.V, sphere.F), Eigen::Affine3d(Eigen::Translation3d(0, 0, 1)), 1, 7);
  scene.commit();
  const std::vector<Material> materials = {{}, {.kind = MaterialKind::kDiffuse, .albedo = Color(0.2f, 0.4f, 0.6f)}};
  const Camera camera = test_support::looking_down(5.0, 60.0);
  const Aovs aovs = render_aovs(scene, materials, camera, 21, 21);
  ASSERT_EQ(aovs.width, 21);
  const std::size_t centre = 10 * 21 + 10, corner = 0;
  EXPECT_GT(aovs.normal[centre].z(), 0.999f);
  EXPECT_NEAR(aovs.depth[centre], 5.0 - 2.0, 2e-3);  // the camera at z 5, the sphere's top at z 2
  EXPECT_TRUE((aovs.albedo[centre] == Color(0.2f, 0.4f, 0.6f)).all());
  EXPECT_EQ(aovs.label[centre], 7.0f);
  EXPECT_EQ(aovs.label[corner], -1.0f);
  EXPECT_EQ(aovs.depth[corner], std::numeric_limits<float>::infinity());
  EXPECT_EQ(aovs.normal[corner].norm(), 0.0f);

  const Aovs crop = render_aovs(scene, materials, camera, 21, 21, {8, 9, 13, 12});
  ASSERT_EQ(crop.width, 5);
  ASSERT_EQ(crop.height, 3);
  EXPECT_EQ(crop.depth[1 * 5 + 2], aovs.depth[centre]);  // (10, 10) is the crop's (2, 1)
  EXPECT_THROW(render_aovs(scene, materials, camera, 21, 21, {0, 0, 22, 5}), std::invalid_argument);
  EXPECT_THROW(render_aovs(scene, {materials[0]}, camera, 21, 21), std::invalid_argument);  // material 1 missing
}

}  // namespace
}  // namespace rice::shading
