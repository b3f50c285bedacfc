// The structured box mesh and the constraint colouring the parallel solver relies on.
#include <gtest/gtest.h>

#include <set>

#include "xpbd/graph_coloring.hpp"
#include "xpbd/tet_mesh.hpp"

namespace rice::xpbd {
namespace {

TEST(BoxTetMesh, TetsArePositiveAndFillTheBox) {
  const TetMesh mesh = make_box_tet_mesh(Vec3(1.0, 0.2, 0.3), 5, 2, 3);
  EXPECT_EQ(mesh.V.rows(), 6 * 3 * 4);
  EXPECT_EQ(mesh.T.rows(), 6 * 5 * 2 * 3);
  const Eigen::VectorXd volumes = tet_volumes(mesh.V, mesh.T);
  EXPECT_GT(volumes.minCoeff(), 0.0);
  EXPECT_NEAR(volumes.sum(), 1.0 * 0.2 * 0.3, 1e-12);
  EXPECT_NEAR(lumped_masses(mesh.V, mesh.T, 1000.0).sum(), 1000.0 * 0.06, 1e-9);
}

TEST(BoxTetMesh, RejectsEmptyGrids) {
  EXPECT_THROW(make_box_tet_mesh(Vec3::Ones(), 0, 1, 1), std::invalid_argument);
  EXPECT_THROW(make_box_tet_mesh(Vec3(1.0, -1.0, 1.0), 1, 1, 1), std::invalid_argument);
}

TEST(GreedyColoring, NoTwoConstraintsOfAColourShareAParticle) {
  const TetMesh mesh = make_box_tet_mesh(Vec3::Ones(), 4, 4, 4);
  std::vector<int> ids(mesh.T.data(), mesh.T.data() + mesh.T.size());
  const Coloring coloring = greedy_coloring(ids, 4, static_cast<int>(mesh.V.rows()));
  EXPECT_EQ(coloring.order.size(), static_cast<size_t>(mesh.T.rows()));
  std::set<int> seen;
  for (int c = 0; c < coloring.colors(); ++c) {
    std::set<int> particles;
    for (const int t : coloring.color(c)) {
      EXPECT_TRUE(seen.insert(t).second) << "tet " << t << " coloured twice";
      for (int k = 0; k < 4; ++k)
        EXPECT_TRUE(particles.insert(mesh.T(t, k)).second) << "colour " << c << " shares particle";
    }
  }
  EXPECT_EQ(seen.size(), static_cast<size_t>(mesh.T.rows()));
  EXPECT_LE(coloring.colors(), 40);
}

}  // namespace
}  // namespace rice::xpbd
