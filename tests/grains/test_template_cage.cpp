// The template cage (grains/template_cage.hpp): its size, its tets' orientation, and that it
// encloses the grain it is made for, so the grain's embedding in it has no negative weight.
#include <gtest/gtest.h>

#include "grains/embedding.hpp"
#include "grains/grain_generator.hpp"
#include "grains/tet_quality.hpp"

namespace rice::grains {
namespace {

Grain caged_grain(const char* cultivar, int stations, std::uint64_t seed) {
  GrainRecipe recipe;
  recipe.cultivar = cultivar_by_name(cultivar);
  recipe.cage = TemplateCageParameters{.stations = stations};
  return make_grain(recipe, seed);
}

TEST(TemplateCage, HasFourVerticesAStationAndTwoTipsAndPositiveTets) {
  for (const int stations : {1, 2, 3}) {
    const Grain grain = caged_grain("japonica", stations, 3);
    EXPECT_EQ(grain.simulation.V.rows(), 4 * stations + 2);
    EXPECT_EQ(grain.simulation.T.rows(), 6 * (stations - 1) + 4);
    const TetQuality q = measure_tet_quality(grain.simulation);
    EXPECT_GT(q.min_volume, 0.0);
    EXPECT_GT(q.min_dihedral_degrees, 20.0);  // 25-43 deg measured: no slivers
    // Bounded: a diamond section around a grain's oval one, widened at the ends for the blunt
    // tips, makes the cage 1.9-2.3 times as thick as the grain (measured), and longer by the
    // tips' extension.
    const Vec3 cage = grain.simulation.V.colwise().maxCoeff() - grain.simulation.V.colwise().minCoeff();
    const Vec3 base = grain.base.V.colwise().maxCoeff() - grain.base.V.colwise().minCoeff();
    EXPECT_LT(cage.x(), 2.0 * base.x());
    EXPECT_LT(cage.z(), 2.5 * base.z());
  }
}

TEST(TemplateCage, EnclosesTheBaseSurfaceAndTheRenderMeshOfEveryCultivar) {
  for (const char* cultivar : {"japonica", "indica", "aromatic", "glutinous"}) {
    SCOPED_TRACE(cultivar);
    const Grain grain = caged_grain(cultivar, 2, 5);
    EXPECT_TRUE(grain.caged);
    const Embedding base = embed_points(grain.base.V, grain.simulation);
    EXPECT_GE(base.weights.minCoeff(), -1e-9);
    EXPECT_GE(grain.embedding.weights.minCoeff(), -1e-9);
  }
}

}  // namespace
}  // namespace rice::grains

namespace rice::grains {
namespace {

TEST(TemplateCage, RefusesBadParametersAndPointsInAPlane) {
  Vertices flat(4, 3);
  flat << 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0;
  EXPECT_THROW(make_template_cage(flat), std::invalid_argument);
  Vertices points(6, 3);
  points << -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  EXPECT_NO_THROW(make_template_cage(points));
  EXPECT_THROW(make_template_cage(points, {.stations = 0}), std::invalid_argument);
  EXPECT_THROW(make_template_cage(points, {.tip_extension = 0.0}), std::invalid_argument);
  EXPECT_THROW(make_template_cage(points, {.margin = -0.1}), std::invalid_argument);
}

}  // namespace
}  // namespace rice::grains
