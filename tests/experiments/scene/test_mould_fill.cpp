// Filling a mould (experiments/mould_fill.hpp) and mesh colliders (collider_grid.hpp): a
// hollow cube's room is its inside, every lattice box lies in it, the lattice runs from the
// bottom up and fills the cube but for a cell's margin; free points keep their distance from
// the grains already in. The cut through a pile (pile_section.hpp) covers a cube's square,
// turned or not, counts overlapping meshes once and gives the packing fraction of a region.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "experiments/scene/collider_grid.hpp"
#include "experiments/scene/mould_fill.hpp"
#include "experiments/pile/pile_section.hpp"

namespace rice::experiments {
namespace {

using xpbd::Vec3;

/// A closed cube of `side` [m] about the origin, faces outward.
grains::SurfaceMesh cube(double side) {
  grains::SurfaceMesh mesh;
  mesh.V.resize(8, 3);
  for (int k = 0; k < 8; ++k)
    mesh.V.row(k) = 0.5 * side * Eigen::RowVector3d((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
  mesh.F.resize(12, 3);
  mesh.F << 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5;
  return mesh;
}

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
}

TEST(MouldFill, FreePointsKeepTheirClearanceFromTheGrainsIn) {
  const std::vector<Vec3> lattice{Vec3(0, 0, 0), Vec3(0.01, 0, 0), Vec3(0.02, 0, 0), Vec3(0.03, 0, 0)};
  const std::vector<Vec3> free = free_points(lattice, {Vec3(0.001, 0, 0)}, 0.0095);
  ASSERT_EQ(free.size(), 2u);
  EXPECT_EQ(free[0], lattice[2]);
  EXPECT_EQ(free[1], lattice[3]);
  EXPECT_EQ(free_points(lattice, {}, 1.0).size(), lattice.size());
}

TEST(PileSection, ACutThroughCubesCoversTheirSquaresOnce) {
  // A 2 cm cube about the origin, and the same cube turned 45° about z and moved 3 cm along x:
  // at z = 0 each covers 4 cm²; a third cube overlapping the first adds only its own part.
  grains::SurfaceMesh square = cube(0.02), turned = cube(0.02), overlapping = cube(0.02);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  turned.V = (turned.V * turn.transpose()).rowwise() + Eigen::RowVector3d(0.03, 0.0, 0.0);
  overlapping.V.rowwise() += Eigen::RowVector3d(0.01, 0.0, 0.0);  // half over the first
  const double pixel = 1e-4;
  const PileSection section =
      cut_pile({square, turned, overlapping}, 0.0, Eigen::Vector2d(-0.02, -0.02), Eigen::Vector2d(0.05, 0.02), pixel);
  EXPECT_EQ(section.width, 700);
  EXPECT_EQ(section.height, 400);
  const double area = pixel * pixel * std::count(section.inside.begin(), section.inside.end(), 1);
  // 4 cm² + 4 cm² + the overlapping cube's 2 cm² outside the first (the turned square's
  // corner reaches x = 0.03 − 0.0141 < 0.02: the third cube's right half overlaps it a little).
  const double overlap = 0.5 * std::pow(0.02 - (0.03 - 0.01 * std::sqrt(2.0)), 2) * 2.0;
  EXPECT_NEAR(area, 4e-4 + 4e-4 + 2e-4 - overlap, 2e-6);
  EXPECT_TRUE(section.at(200, 200));   // (0, 0): in the first cube
  EXPECT_FALSE(section.at(50, 50));    // (−0.015, −0.015)
  EXPECT_TRUE(section.at(500, 200));   // (0.03, 0): in the turned one
  // The packing fraction of the square |x|, |y| < 1.5 cm: the first cube's 4 cm² and its
  // neighbour's overlap up to x = 1.5 cm, 4 + 1 of 9 cm².
  // The region grows from its seed and stops at the square's edges (a wall beyond it, at
  // |x| = 1.6 cm, is not reached: the ring between is closed).
  const auto square_and_ring = [](const Eigen::Vector2d& p) {
    const double r = p.cwiseAbs().maxCoeff();
    return r < 0.015 || (r > 0.016 && r < 0.018);
  };
  const std::vector<char> region = region_around(section, square_and_ring, Eigen::Vector2d::Zero());
  EXPECT_NEAR(pixel * pixel * std::count(region.begin(), region.end(), 1), 9e-4, 1e-6);
  EXPECT_NEAR(packing_fraction(section, region), 5.0 / 9.0, 0.01);
  // The picture, +y up: a grain white, the region grey, the rest black.
  const RgbImage image = section_image(section, region);
  const auto grey = [&](int i, int j) {
    return image.pixels[3 * (static_cast<size_t>(section.height - 1 - j) * image.width + i)];
  };
  EXPECT_EQ(grey(200, 200), 255);  // in the first cube
  EXPECT_EQ(grey(55, 55), 70);     // (−0.0144, −0.0144): in the square, in no cube
  EXPECT_EQ(grey(5, 5), 0);        // outside the square
  const std::vector<char> in_gap = region_around(section, square_and_ring, Eigen::Vector2d(0.0155, 0.0));
  EXPECT_EQ(std::count(in_gap.begin(), in_gap.end(), 1), 0);  // a seed in the closed gap
  EXPECT_TRUE(std::isnan(packing_fraction(section, std::vector<char>(section.inside.size(), 0))));
  // A cut above every mesh is empty; a bad pixel is refused.
  const PileSection above = cut_pile({square}, 0.05, Eigen::Vector2d(-0.02, -0.02), Eigen::Vector2d(0.02, 0.02), pixel);
  EXPECT_EQ(std::count(above.inside.begin(), above.inside.end(), 1), 0);
  EXPECT_THROW(cut_pile({square}, 0.0, Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones(), 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace rice::experiments
