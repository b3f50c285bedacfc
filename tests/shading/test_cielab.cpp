// CIELAB and ΔE (shading/cielab.hpp) against published values: the white, black, the sRGB
// primaries' L*a*b* (Lindbloom's calculator, D65) and a mid grey.
#include "shading/cielab.hpp"

#include <gtest/gtest.h>

namespace rice::shading {
namespace {

void expect_lab(const Eigen::Vector3d& rgb, double L, double a, double b) {
  const Eigen::Vector3d lab = cielab(rgb);
  EXPECT_NEAR(lab.x(), L, 0.01);
  EXPECT_NEAR(lab.y(), a, 0.01);
  EXPECT_NEAR(lab.z(), b, 0.01);
}

TEST(Cielab, KnownColours) {
  expect_lab({1, 1, 1}, 100.0, 0.0, 0.0);
  expect_lab({0, 0, 0}, 0.0, 0.0, 0.0);
  expect_lab({1, 0, 0}, 53.24, 80.09, 67.20);
  expect_lab({0, 1, 0}, 87.73, -86.18, 83.18);
  expect_lab({0, 0, 1}, 32.30, 79.19, -107.86);
  expect_lab({0.18, 0.18, 0.18}, 49.50, 0.0, 0.0);
}

TEST(Cielab, DeltaEIsTheLabDistance) {
  EXPECT_NEAR(delta_e76({1, 1, 1}, {0, 0, 0}), 100.0, 1e-9);
  EXPECT_NEAR(delta_e76({0.18, 0.18, 0.18}, {0.18, 0.18, 0.18}), 0.0, 1e-12);
  EXPECT_NEAR(delta_e76({0.2, 0.2, 0.2}, {0.18, 0.18, 0.18}), cielab({0.2, 0.2, 0.2}).x() - 49.50, 0.01);
}

}  // namespace
}  // namespace rice::shading
