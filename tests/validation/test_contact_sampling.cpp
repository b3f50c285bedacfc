// Contact sampling: does testing only a grain's simulation-mesh vertices against the other
// grain (a vertex-against-distance-field narrow phase) detect grain–grain crossings, and do the
// collision spheres (grains/collision_spheres.hpp), which xpbd contact uses instead, do better?
// Two copies A and B of one japonica grain (seed 1) cross in an X: B is turned 90° about the
// thickness axis z, shifted in the xy-plane so the crossing falls on a 9 × 9 grid of points
// (steps of L/16), then lowered along z onto A in steps of T/100 from touching. At each step:
//   - vertex contact: some vertex of A lies in one of B's tets or a vertex of B in one of A's;
//   - true depth: the largest distance from a point of one solid, inside the other, to the
//     other's boundary (order-4 barycentric lattice of every tet, so slightly low);
//   - sphere overlap: the largest r_i + r_j − |c_i − c_j| over A's and B's spheres.
// Measured (Release, gcc; 25 vertices, 46 tets, 18 spheres, T = 2.10 mm, 0.6 s): vertices
// alone miss edge-on-edge crossings up to 0.077 T deep (0.16 mm; 0.048 T with clang, whose
// grain differs in the last bits), and the spheres catch that one
// (overlap +0.022 T). But no vertex miss reaches 10% of T, and at 80 of the 81 crossing points
// the vertices detect contact first: the union is inscribed, up to the 0.12 T fit tolerance
// inside the surface, so it first overlaps at depths 0.05–0.20 T. The sphere catch depends on
// the grid: on a 5 × 5 grid (L/12) the deepest miss is 0.04 T and the spheres miss it too.
// Rolling B about its length by 15–90° (5 × 5 grid, explored while writing this) gave misses
// up to 0.09 T and the spheres first at 4 of 175 configurations. So on this grain the measured
// case for spheres is not that vertices miss deep crossings.
// Run: cmake --build build --target test_validation -j1 &&
//      build/tests/test_validation --gtest_filter='ContactSampling*'
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "grains/collision_spheres.hpp"
#include "grains/embedding.hpp"
#include "grains/grain_generator.hpp"
#include "grains/mesh_topology.hpp"
#include "grains/surface_measures.hpp"

namespace rice {
namespace {

using grains::Vec3;
using grains::VolumeMesh;

/// A tet mesh as a solid: point-in-tet through each tet's inverse affine map, and the
/// distance to its boundary surface.
class Solid {
 public:
  explicit Solid(const VolumeMesh& mesh)
      : boundary_(grains::boundary_surface(mesh)), lower_(mesh.V.colwise().minCoeff()), upper_(mesh.V.colwise().maxCoeff()) {
    for (Eigen::Index t = 0; t < mesh.T.rows(); ++t) {
      const auto c = grains::tet_corners(mesh, t);
      Eigen::Matrix3d edges;
      edges << c[1] - c[0], c[2] - c[0], c[3] - c[0];
      origins_.push_back(c[0]);
      inverses_.push_back(edges.inverse());
    }
  }

  /// Inside or on the boundary.
  bool contains(const Vec3& p) const {
    if ((p.array() < lower_.array()).any() || (p.array() > upper_.array()).any()) return false;
    for (std::size_t t = 0; t < origins_.size(); ++t) {
      const Vec3 w = inverses_[t] * (p - origins_[t]);
      if (std::min(w.minCoeff(), 1.0 - w.sum()) >= -1e-12) return true;
    }
    return false;
  }

  /// How deep p lies inside: its distance to the boundary, 0 outside.
  double depth(const Vec3& p) const {
    if (!contains(p)) return 0.0;
    double distance = INFINITY;
    for (Eigen::Index f = 0; f < boundary_.F.rows(); ++f) {
      const auto c = grains::triangle_corners(boundary_, f);
      distance = std::min(distance, grains::point_triangle_distance(p, c[0], c[1], c[2]));
    }
    return distance;
  }

 private:
  grains::SurfaceMesh boundary_;
  Vec3 lower_, upper_;  // bounding box
  std::vector<Vec3> origins_;
  std::vector<Eigen::Matrix3d> inverses_;
};

/// The points of an order-n barycentric lattice in every tet.
std::vector<Vec3> tet_samples(const VolumeMesh& mesh, int n) {
  std::vector<Vec3> samples;
  for (Eigen::Index t = 0; t < mesh.T.rows(); ++t) {
    const auto c = grains::tet_corners(mesh, t);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        for (int k = 0; i + j + k <= n; ++k) samples.push_back((i * c[1] + j * c[2] + k * c[3] + (n - i - j - k) * c[0]) / n);
  }
  return samples;
}

/// What each contact test sees with A at rest and B, a copy of A, placed by `b`.
struct Probe {
  bool vertex_inside = false;  ///< a vertex of A in B's solid or one of B in A's
  double depth = 0.0;          ///< true interpenetration [m]
  double sphere_overlap = 0.0;  ///< largest overlap of an A sphere and a B sphere [m], < 0 apart
};

class CrossedPair {
 public:
  explicit CrossedPair(const VolumeMesh& mesh)
      : mesh_(mesh), solid_(mesh), samples_(tet_samples(mesh, 4)), spheres_(grains::fit_collision_spheres(mesh)) {}

  Probe probe(const Eigen::Isometry3d& b) const {
    const Eigen::Isometry3d b_inverse = b.inverse();  // A's frame as seen from B
    Probe result;
    for (Eigen::Index v = 0; v < mesh_.V.rows() && !result.vertex_inside; ++v) {
      const Vec3 p = mesh_.V.row(v).transpose();
      result.vertex_inside = solid_.contains(b * p) || solid_.contains(b_inverse * p);
    }
    for (const Vec3& p : samples_) result.depth = std::max({result.depth, solid_.depth(b * p), solid_.depth(b_inverse * p)});
    result.sphere_overlap = -INFINITY;
    for (Eigen::Index i = 0; i < spheres_.radii.size(); ++i)
      for (Eigen::Index j = 0; j < spheres_.radii.size(); ++j) {
        const Vec3 ci = spheres_.centres.row(i).transpose(), cj = b * Vec3(spheres_.centres.row(j).transpose());
        result.sphere_overlap = std::max(result.sphere_overlap, spheres_.radii[i] + spheres_.radii[j] - (ci - cj).norm());
      }
    return result;
  }

 private:
  const VolumeMesh& mesh_;
  Solid solid_;
  std::vector<Vec3> samples_;
  grains::CollisionSpheres spheres_;
};

/// One crossing point lowered until both tests report contact.
struct Descent {
  Probe deepest_missed;        ///< the deepest step with no vertex inside
  double sphere_depth = 0.0;  ///< true depth at the first step where the spheres overlap [m]
};

Descent lower_onto(const CrossedPair& pair, const Vec3& crossing, double thickness) {
  const Eigen::AngleAxisd quarter_turn(M_PI / 2, Vec3::UnitZ());
  Descent descent;
  bool vertex_seen = false, sphere_seen = false;
  for (int step = 0; !(vertex_seen && sphere_seen); ++step) {
    const double offset = thickness * (1.0 - step / 100.0);  // z-extents just touch at step 0
    const Probe probe = pair.probe(Eigen::Translation3d(crossing + offset * Vec3::UnitZ()) * quarter_turn);
    vertex_seen = vertex_seen || probe.vertex_inside;
    if (!vertex_seen) descent.deepest_missed = probe;
    if (!sphere_seen && probe.sphere_overlap > 0.0) descent.sphere_depth = probe.depth;
    sphere_seen = sphere_seen || probe.sphere_overlap > 0.0;
  }
  return descent;
}

TEST(ContactSampling, VerticesAloneMissOnlyShallowCrossings) {
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  const grains::Grain grain = grains::make_grain(recipe, 1, 1.0);
  const Vec3 extent = grains::bounding_box_extent(grain.simulation.V);
  ASSERT_TRUE(extent.x() > extent.y() && extent.y() > extent.z()) << "length along x, thickness along z";
  const double length = extent.x(), thickness = extent.z();
  const CrossedPair pair(grain.simulation);

  Probe worst_missed;
  int crossings = 0, spheres_first = 0;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      const Descent descent = lower_onto(pair, Vec3(i * length / 16, j * length / 16, 0.0), thickness);
      if (descent.deepest_missed.depth > worst_missed.depth) worst_missed = descent.deepest_missed;
      ++crossings;
      if (descent.sphere_depth <= descent.deepest_missed.depth) ++spheres_first;
    }
  RecordProperty("deepest_vertex_miss_over_T", std::to_string(worst_missed.depth / thickness));
  RecordProperty("sphere_overlap_there_over_T", std::to_string(worst_missed.sphere_overlap / thickness));
  RecordProperty("crossings_where_spheres_come_first", std::to_string(spheres_first) + " of " + std::to_string(crossings));

  // Vertices alone miss edge-on-edge crossings, but none of 10% of the thickness (whether the
  // spheres catch the deepest one depends on the grid, so it is recorded, not checked) ...
  EXPECT_GT(worst_missed.depth, 0.03 * thickness);
  EXPECT_LT(worst_missed.depth, 0.10 * thickness);
  // ... and the spheres, inscribed, lag the vertices at nearly every crossing point.
  EXPECT_LE(spheres_first, crossings / 10);
}

}  // namespace
}  // namespace rice
