// Porous level sets: sphere SDF against the analytic distance, porosity against its target,
// the render mesh closed, manifold and of the level set's volume.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "grains/base_shape.hpp"
#include "grains/grain_generator.hpp"
#include "grains/level_set_mesh.hpp"
#include "grains/mesh_topology.hpp"
#include "grains/porous_level_set.hpp"
#include "grains/surface_measures.hpp"

namespace rice::grains {
namespace {

GrainShape fat_ellipsoid() {
  GrainShape shape;
  shape.length = 8e-3;
  shape.width = 5e-3;
  shape.thickness = 5e-3;
  return shape;
}

// Every active voxel within the narrow band holds |x − c| − r (as OpenVDB's own test does
// against brute force).
TEST(PorousLevelSet, SingleSphereIsTheAnalyticDistanceInTheNarrowBand) {
  const double voxel = 0.05e-3, band = 3.0;
  const Sphere sphere{Vec3(0.11e-3, -0.23e-3, 0.07e-3), 0.4e-3};
  long skipped = -1;
  const auto grid = spheres_level_set({sphere}, voxel, band, &skipped);
  EXPECT_EQ(skipped, 0);
  long checked = 0;
  double worst = 0.0;
  for (auto it = grid->cbeginValueOn(); it; ++it) {
    const openvdb::Vec3d p = grid->indexToWorld(it.getCoord());
    const double exact = (Vec3(p.x(), p.y(), p.z()) - sphere.centre).norm() - sphere.radius;
    if (std::abs(exact) > (band - 1.0) * voxel) continue;
    worst = std::max(worst, std::abs(*it - exact));
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst, 1e-3 * voxel);
  // Eight voxels per radius: the measured volume is within 2%.
  const double exact_volume = 4.0 / 3.0 * std::numbers::pi * std::pow(sphere.radius, 3);
  EXPECT_NEAR(level_set_volume(*grid) / exact_volume, 1.0, 0.02);
}

TEST(PorousLevelSet, SpheresUnderOneAndAHalfVoxelsAreCountedAsSkipped) {
  long skipped = 0;
  spheres_level_set({{Vec3::Zero(), 0.05e-3}, {Vec3(1e-3, 0, 0), 0.2e-3}}, 0.05e-3, 3.0, &skipped);
  EXPECT_EQ(skipped, 1);
}

// The mesh's distance field matches the analytic ellipsoid distance near its axes' ends.
TEST(PorousLevelSet, BaseSignedDistanceFieldIsEuclideanAndFilledInside) {
  const GrainShape shape = fat_ellipsoid();
  const auto sdf = signed_distance_field(make_base_shape(shape, {64, 64}), 0.1e-3, 3.0);
  const auto accessor = sdf->getConstAccessor();
  const auto value_at = [&](const Vec3& p) {
    return accessor.getValue(sdf->transform().worldToIndexNodeCentered(openvdb::Vec3d(p.x(), p.y(), p.z())));
  };
  // Centre: depth = half the smallest axis; just outside the tip: 0.2 mm.
  EXPECT_NEAR(value_at(Vec3::Zero()), -0.5 * shape.thickness, 0.05e-3);
  EXPECT_NEAR(value_at(Vec3(0.5 * shape.length + 0.2e-3, 0, 0)), 0.2e-3, 0.02e-3);
}

TEST(PorousLevelSet, CorePorosityFollowsItsParameter) {
  const SurfaceMesh base = make_base_shape(fat_ellipsoid(), {48, 48});
  PorosityParameters parameters;
  parameters.bump_count = 0;
  parameters.pore_radius_min = 0.15e-3;
  parameters.pore_radius_max = 0.3e-3;
  parameters.skin_thickness = 0.2e-3;
  double previous = 0.0;
  for (const double target : {0.1, 0.25, 0.4}) {
    parameters.core_porosity = target;
    RandomStream random(11);
    const PorousLevelSet grain = make_porous_level_set(base, parameters, random);
    EXPECT_GT(grain.inner_core_volume, 0.1 * grain.solid_volume);
    EXPECT_NEAR(grain.measured_core_porosity, target, 0.04) << "pores " << grain.pore_count;
    EXPECT_GT(grain.measured_core_porosity, previous);
    EXPECT_EQ(grain.spheres_skipped, 0);
    previous = grain.measured_core_porosity;
  }
}

TEST(PorousLevelSet, RenderMeshIsClosedManifoldAndKeepsTheLevelSetVolume) {
  for (const std::string& name : cultivar_names()) {
    RandomStream random(2024);
    const GrainShape shape = sample_grain_shape(cultivar_by_name(name), random);
    const PorousLevelSet grain = make_porous_level_set(make_base_shape(shape), PorosityParameters{}, random);
    EXPECT_GT(grain.pore_count, 0) << name;
    EXPECT_GT(grain.porosity(), 0.0) << name;
    for (const double adaptivity : {0.0, GrainRecipe{}.mesh_adaptivity}) {
      const SurfaceMesh mesh = level_set_to_mesh(*grain.grid, adaptivity);
      const auto defect = closed_manifold_defect(mesh);
      EXPECT_FALSE(defect.has_value()) << name << ", adaptivity " << adaptivity << ": " << *defect;
      EXPECT_NEAR(enclosed_volume(mesh) / grain.porous_volume, 1.0, 0.02) << name << ", adaptivity " << adaptivity;
    }
  }
}

TEST(PorousLevelSet, BadParametersAreRefusedByName) {
  PorosityParameters parameters;
  parameters.pore_radius_min = -1e-4;
  try {
    validate(parameters);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pore radii"), std::string::npos) << e.what();
  }
  parameters = {};
  parameters.core_porosity = 0.95;
  EXPECT_THROW(validate(parameters), std::invalid_argument);
}

}  // namespace
}  // namespace rice::grains
