// Collision spheres (collision_spheres.hpp) on the simulation meshes of every cultivar: every
// sphere inside the mesh, the union within the tolerance of the boundary everywhere sampled,
// a sphere count that keeps contact cheap, determinism, and refused parameters.
#include <gtest/gtest.h>

#include "grains/collision_spheres.hpp"
#include "grains/cultivar.hpp"
#include "grains/base_shape.hpp"
#include "grains/embedding.hpp"
#include "grains/mesh_topology.hpp"
#include "grains/random_stream.hpp"
#include "grains/simulation_mesh.hpp"
#include "grains/surface_measures.hpp"

namespace rice::grains {
namespace {

/// Distance from p to the mesh's boundary surface, negative inside (every sample point of a
/// closed mesh: the sign from the tet that holds p).
double signed_distance_to_boundary(const VolumeMesh& mesh, const Vec3& p) {
  double distance = INFINITY;
  for (const BoundaryFace& face : boundary_faces(mesh.T))
    distance = std::min(distance, point_triangle_distance(p, mesh.V.row(face.corners[0]), mesh.V.row(face.corners[1]),
                                                          mesh.V.row(face.corners[2])));
  const Embedding e = embed_points(p.transpose(), mesh);
  return e.weights.row(0).minCoeff() >= -1e-12 ? -distance : distance;
}

TEST(CollisionSpheres, FollowEveryCultivarsSurfaceWithinTheTolerance) {
  const CollisionSphereParameters parameters;
  for (const std::string& name : cultivar_names()) {
    RandomStream random(7);
    const SurfaceMesh base = make_base_shape(sample_grain_shape(cultivar_by_name(name), random));
    const VolumeMesh mesh = make_simulation_mesh(base, {}, 7);
    const double thickness = bounding_box_extent(mesh.V).minCoeff();
    const CollisionSpheres spheres = fit_collision_spheres(mesh, parameters);
    EXPECT_EQ(spheres.uncovered_samples, 0) << name;
    EXPECT_LE(spheres.max_gap, parameters.tolerance * thickness) << name;
    EXPECT_LE(spheres.radii.size(), parameters.max_spheres) << name;
    for (int k = 0; k < spheres.radii.size(); ++k) {
      // Inscribed, up to the distance field's voxel error.
      const double depth = -signed_distance_to_boundary(mesh, spheres.centres.row(k).transpose());
      EXPECT_LE(spheres.radii[k], depth + parameters.voxel_size * thickness) << name << " sphere " << k;
    }
    // The boundary surface the spheres follow is the closed surface of the mesh.
    EXPECT_FALSE(closed_manifold_defect(boundary_surface(mesh)).has_value()) << name;
    RecordProperty(name + "_spheres", static_cast<int>(spheres.radii.size()));
  }
}

TEST(CollisionSpheres, AreDeterministicAndRefuseBadParameters) {
  RandomStream random(3);
  const VolumeMesh mesh = make_simulation_mesh(make_base_shape(sample_grain_shape(cultivar_by_name("indica"), random)), {}, 3);
  const CollisionSpheres a = fit_collision_spheres(mesh), b = fit_collision_spheres(mesh);
  EXPECT_EQ(a.centres, b.centres);
  EXPECT_EQ(a.radii, b.radii);
  CollisionSphereParameters bad;
  bad.tolerance = 0.0;
  EXPECT_THROW(fit_collision_spheres(mesh, bad), std::invalid_argument);
  bad = {};
  bad.max_spheres = 0;
  EXPECT_THROW(fit_collision_spheres(mesh, bad), std::invalid_argument);
}

}  // namespace
}  // namespace rice::grains
