// The procedural chawan: closed, manifold and outward; its stated size; its volume against
// the closed form of its profile (Pappus); walls that would cross are refused.
#include <gtest/gtest.h>

#include <cmath>

#include "grains/chawan.hpp"
#include "grains/mesh_topology.hpp"
#include "grains/surface_measures.hpp"

namespace rice::grains {
namespace {

/// Volume of the solid of revolution of the default profile, by the difference of the outer
/// and inner half-ellipsoid caps and the foot cylinder, with the polygonal profile's error
/// left to the tolerance.
double expected_volume(const ChawanShape& s) {
  // Outer: the solid under the rim plane and above the outer wall, z from foot_height up.
  const double outer_b = s.height - s.foot_height, inner_a = s.rim_radius - s.wall_thickness;
  const double half_ellipsoid = [&] { return 2.0 / 3.0 * M_PI * s.rim_radius * s.rim_radius * outer_b; }();
  const double inner = 2.0 / 3.0 * M_PI * inner_a * inner_a * s.inner_depth;
  // The outer half-ellipsoid below z = height, cut at r < foot_radius by the foot cylinder,
  // which fills from z = 0 to the wall.
  const auto outer_z = [&](double r) { return s.height - outer_b * std::sqrt(1.0 - std::pow(r / s.rim_radius, 2)); };
  double foot = 0.0;  // ∫ 2πr (outer_z(r) − 0) dr over [0, foot_radius], minus the cap part below foot_height there
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    const double r = (k + 0.5) * s.foot_radius / n;
    foot += 2.0 * M_PI * r * (outer_z(r) - s.foot_height) * s.foot_radius / n;  // cap region filled by the foot
    foot += 2.0 * M_PI * r * s.foot_height * s.foot_radius / n;                  // below the cap's lowest point
  }
  return half_ellipsoid - inner + foot;
}

TEST(Chawan, IsAClosedOutwardBowlOfTheStatedSize) {
  const ChawanShape shape;
  const SurfaceMesh bowl = make_chawan(shape);
  EXPECT_FALSE(closed_manifold_defect(bowl).has_value());
  EXPECT_GT(enclosed_volume(bowl), 0.0);
  const Vec3 extent = bounding_box_extent(bowl.V);
  EXPECT_NEAR(extent.x(), 0.12, 1e-12);
  EXPECT_NEAR(extent.z(), 0.065, 1e-12);
  EXPECT_NEAR(bowl.V.col(2).minCoeff(), 0.0, 1e-15);
  // Polygonal walls (24 profile points, 64 around) sit inside the smooth ones.
  EXPECT_NEAR(enclosed_volume(bowl), expected_volume(shape), 0.02 * expected_volume(shape));
}

TEST(Chawan, AScaledBowlIsTheSameBowlLargerOrSmaller) {
  const SurfaceMesh bowl = make_chawan(), half = make_chawan(scaled({}, 0.5));
  ASSERT_EQ(half.V.rows(), bowl.V.rows());
  EXPECT_LT((half.V - 0.5 * bowl.V).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(half.F, bowl.F);
}

TEST(Chawan, CrossingWallsAndBadSizesAreRefused) {
  ChawanShape shape;
  shape.inner_depth = 0.064;  // the inside bottom would pass through the foot
  EXPECT_THROW(make_chawan(shape), std::invalid_argument);
  shape = {};
  shape.wall_thickness = -1e-3;
  EXPECT_THROW(make_chawan(shape), std::invalid_argument);
}

}  // namespace
}  // namespace rice::grains
