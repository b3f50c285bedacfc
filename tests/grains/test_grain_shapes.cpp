// Cultivar sampling and the parametric base surface.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "grains/base_shape.hpp"
#include "grains/cultivar.hpp"
#include "grains/mesh_topology.hpp"
#include "grains/surface_measures.hpp"

namespace rice::grains {
namespace {

TEST(Cultivar, UnknownNameListsTheKnownOnes) {
  try {
    cultivar_by_name("arborio");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("japonica, indica, aromatic, glutinous"), std::string::npos) << e.what();
  }
}

TEST(Cultivar, SwellFactorOutsideOneToOneAndAHalfIsRefused) {
  Cultivar c = cultivar_by_name("japonica");
  c.swell_max = 1.6;
  EXPECT_THROW(validate(c), std::invalid_argument);
  c.swell_max = 1.4;
  c.swell_min = 0.9;
  EXPECT_THROW(validate(c), std::invalid_argument);
  for (const std::string& name : cultivar_names()) EXPECT_NO_THROW(validate(cultivar_by_name(name))) << name;
}

// Sample means match the cooked dimensions the cultivar stands for: P times the
// volume-neutral proportions times the raw means.
TEST(Cultivar, SampledDimensionsFollowTheirDistributions) {
  for (const std::string& name : cultivar_names()) {
    const Cultivar c = cultivar_by_name(name);
    RandomStream random(7);
    const int n = 4000;
    double length = 0.0, swell = 0.0, swell_min = 2.0, swell_max = 0.0;
    for (int i = 0; i < n; ++i) {
      const GrainShape shape = sample_grain_shape(c, random);
      length += shape.length / n;
      swell += shape.swell / n;
      swell_min = std::min(swell_min, shape.swell);
      swell_max = std::max(swell_max, shape.swell);
    }
    const double neutral = std::cbrt(c.cooked_length_ratio * c.cooked_width_ratio * c.cooked_thickness_ratio);
    const double expected = c.length.mean * c.cooked_length_ratio / neutral;
    EXPECT_NEAR(length, expected, 4.0 * c.length.standard_deviation / std::sqrt(double(n))) << name;
    EXPECT_NEAR(swell, 0.5 * (c.swell_min + c.swell_max), 0.01) << name;
    EXPECT_GE(swell_min, c.swell_min);
    EXPECT_LE(swell_max, c.swell_max);
  }
  // Basmati roughly doubles its length on cooking (at the mean P).
  const Cultivar basmati = cultivar_by_name("aromatic");
  RandomStream random(1);
  const GrainShape shape = sample_grain_shape(basmati, random);
  EXPECT_GT(shape.length * 0.5 * (basmati.swell_min + basmati.swell_max) / basmati.length.mean, 1.7);
}

TEST(BaseShape, IsClosedManifoldAndOutward) {
  for (const std::string& name : cultivar_names()) {
    RandomStream random(3);
    const GrainShape shape = sample_grain_shape(cultivar_by_name(name), random);
    const SurfaceMesh mesh = make_base_shape(shape);
    EXPECT_FALSE(closed_manifold_defect(mesh).has_value()) << name << ": " << *closed_manifold_defect(mesh);
    EXPECT_GT(enclosed_volume(mesh), 0.0) << name;
    const Vec3 extent = bounding_box_extent(mesh.V);
    EXPECT_NEAR(extent.x(), shape.length, 0.02 * shape.length) << name;  // the notch trims a tip
    EXPECT_NEAR(extent.y(), shape.width, 0.02 * shape.width) << name;
    EXPECT_NEAR(extent.z(), shape.thickness, 0.02 * shape.thickness) << name;
  }
}

// With p = 2, no asymmetry and no notch the surface is an ellipsoid: the tessellated volume
// converges to π L W T / 6 at second order in the ring spacing.
TEST(BaseShape, EllipsoidVolumeConvergesToAnalytic) {
  GrainShape shape;
  shape.length = 7e-3;
  shape.width = 3e-3;
  shape.thickness = 2e-3;
  const double exact = std::numbers::pi * shape.length * shape.width * shape.thickness / 6.0;
  double previous_error = 1.0;
  for (int n : {16, 32, 64}) {
    const double error = std::abs(enclosed_volume(make_base_shape(shape, {n, n})) / exact - 1.0);
    EXPECT_LT(error, previous_error / 3.0) << n;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 3e-3);
}

TEST(BaseShape, NotchRemovesVolumeAndKeepsTheSurfaceValid) {
  RandomStream random(5);
  GrainShape shape = sample_grain_shape(cultivar_by_name("japonica"), random);
  const double with_notch = enclosed_volume(make_base_shape(shape));
  shape.notch_depth = 0.0;
  const double without = enclosed_volume(make_base_shape(shape));
  EXPECT_LT(with_notch, without * 0.995);
  EXPECT_GT(with_notch, without * 0.9);
}

}  // namespace
}  // namespace rice::grains
