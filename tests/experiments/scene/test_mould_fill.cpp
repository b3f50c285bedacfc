// Filling a mould (experiments/scene/mould_fill.hpp) and mesh colliders (collider_grid.hpp):
// a hollow cube's room is its inside, every lattice box lies in it, the lattice runs from the
// bottom up and fills the cube but for a cell's margin, a shifted lattice is the same moved;
// free points keep their distance from the grains already in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "experiments/scene/collider_grid.hpp"
#include "experiments/scene/mould_fill.hpp"
#include "tests/common/cube_mesh.hpp"

namespace rice::experiments {
namespace {

using xpbd::Vec3;

using rice::test_support::cube;

xpbd::Collider mould_of(const grains::SurfaceMesh& mesh, bool hollow) {
  xpbd::Collider c;
  c.shape = xpbd::ColliderShape::kDistanceGrid;
  c.grid = std::make_shared<const xpbd::DistanceGrid>(distance_grid_of(mesh, 1e-3, 0.01, hollow));
  c.motion.front().translation = Vec3(0.0, 0.0, 0.05);  // standing on z = 0
  return c;
}

TEST(MouldFill, AHollowCubeHoldsItsLatticeOfBoxesFromTheBottomUp) {
  const double side = 0.1;
  const xpbd::Collider mould = mould_of(cube(side), /*hollow=*/true);
  // Inside a hollow mesh φ > 0 (room), outside it φ < 0 (solid).
  EXPECT_GT(xpbd::local_signed_distance(mould, Vec3::Zero()).distance, 0.04);
  EXPECT_LT(xpbd::local_signed_distance(mould, Vec3(0.0, 0.0, 0.053)).distance, 0.0);
  const Vec3 cell(0.008, 0.004, 0.003);
  const std::vector<Vec3> lattice = mould_lattice(mould, cell);
  // Every box inside the cube (to the grid's accuracy), and the cube filled but for about a
  // cell at each wall.
  for (const Vec3& c : lattice) {
    EXPECT_LE((c - Vec3(0.0, 0.0, 0.05)).cwiseAbs().maxCoeff() + 0.5 * cell.minCoeff(), 0.5 * side + 1e-3);
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_LE(std::abs(c[axis] - (axis == 2 ? 0.05 : 0.0)) + 0.5 * cell[axis], 0.5 * side + 1e-3);
  }
  const double full = (side / cell.x()) * (side / cell.y()) * (side / cell.z());
  const double margin = ((side - 2 * cell.x()) / cell.x()) * ((side - 2 * cell.y()) / cell.y()) *
                        ((side - 2 * cell.z()) / cell.z());
  EXPECT_LE(lattice.size(), full);
  EXPECT_GE(lattice.size(), margin);
  EXPECT_TRUE(std::is_sorted(lattice.begin(), lattice.end(), [](const Vec3& a, const Vec3& b) { return a.z() < b.z(); }));
  // Laid as bricks: a point of the next layer up sits over the corner of four boxes below.
  const Vec3 first = lattice.front();
  const auto above =
      std::find_if(lattice.begin(), lattice.end(), [&](const Vec3& c) { return c.z() > first.z() + 1e-9; });
  ASSERT_NE(above, lattice.end());
  EXPECT_NEAR(above->z() - first.z(), cell.z(), 1e-9);
  for (int axis = 0; axis < 2; ++axis) {
    const double offset = std::fmod(above->coeff(axis) - first[axis], cell[axis]) / cell[axis];
    EXPECT_NEAR(std::abs(offset), 0.5, 1e-9) << axis;
  }
  // A solid cube's room is outside it: no lattice point inside.
  for (const Vec3& c : mould_lattice(mould_of(cube(side), /*hollow=*/false), cell))
    EXPECT_GT((c - Vec3(0.0, 0.0, 0.05)).cwiseAbs().maxCoeff(), 0.5 * side);
  EXPECT_THROW(mould_lattice(xpbd::Collider{}, cell), std::invalid_argument);
  EXPECT_THROW(mould_lattice(mould, Vec3(0.0, 1.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(mould_lattice(mould, cell, Vec3(0.0, 1.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(mould_lattice(mould, cell, Vec3(-0.1, 0.0, 0.0)), std::invalid_argument);
}

TEST(MouldFill, AShiftedLatticeIsTheLatticeMovedByItsShiftWhereItsBoxesStayInTheRoom) {
  const double side = 0.1;
  const xpbd::Collider mould = mould_of(cube(side), /*hollow=*/true);
  const Vec3 cell(0.008, 0.004, 0.003), shift(0.3, 0.7, 0.0);
  const std::vector<Vec3> lattice = mould_lattice(mould, cell), shifted = mould_lattice(mould, cell, shift);
  ASSERT_FALSE(shifted.empty());
  // Each shifted point is a point of the lattice moved by the shift, and its box is in the cube.
  int matched = 0;
  for (const Vec3& c : shifted) {
    const Vec3 unshifted = c - shift.cwiseProduct(cell);
    const auto same = [&](const Vec3& p) { return (p - unshifted).norm() < 1e-9; };
    matched += std::any_of(lattice.begin(), lattice.end(), same);
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_LE(std::abs(c[axis] - (axis == 2 ? 0.05 : 0.0)) + 0.5 * cell[axis], 0.5 * side + 1e-3);
  }
  // All but those whose unshifted box crossed a wall that the shift took it from: a layer of
  // boxes at the x wall and one at the y wall at most.
  const double wall_layers = side / cell.y() * side / cell.z() + side / cell.x() * side / cell.z();
  EXPECT_GE(matched, static_cast<double>(shifted.size()) - wall_layers);
  EXPECT_NEAR(static_cast<double>(shifted.size()), static_cast<double>(lattice.size()), 0.1 * lattice.size());
}

TEST(MouldFill, FreePointsKeepTheirClearanceFromTheGrainsIn) {
  const std::vector<Vec3> lattice{Vec3(0, 0, 0), Vec3(0.01, 0, 0), Vec3(0.02, 0, 0), Vec3(0.03, 0, 0)};
  const std::vector<Vec3> free = free_points(lattice, {Vec3(0.001, 0, 0)}, 0.0095);
  ASSERT_EQ(free.size(), 2u);
  EXPECT_EQ(free[0], lattice[2]);
  EXPECT_EQ(free[1], lattice[3]);
  EXPECT_EQ(free_points(lattice, {}, 1.0).size(), lattice.size());
}

}  // namespace
}  // namespace rice::experiments
