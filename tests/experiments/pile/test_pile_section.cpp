// The cut through a pile (experiments/pile/pile_section.hpp) covers a cube's square, turned or
// not, counts overlapping meshes once and gives the packing fraction of a region.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "experiments/pile/pile_section.hpp"
#include "tests/common/cube_mesh.hpp"

namespace rice::experiments {
namespace {

using rice::test_support::cube;

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
