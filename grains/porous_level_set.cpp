// Porous level set: base SDF, surface bumps, core pores, CSG (see porous_level_set.hpp).
#include "grains/porous_level_set.hpp"

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace rice::grains {
namespace {

// OpenVDB's particle rasteriser drops spheres under this radius (its Nyquist limit).
constexpr double kMinimumRadiusInVoxels = 1.5;

void check_porosity(bool ok, const std::string& parameter, const std::string& expected) {
  if (!ok) throw std::invalid_argument("porosity parameter " + parameter + " must be " + expected);
}

void initialize_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

// The particle-list interface particlesToSdf expects.
struct SphereList {
  using PosType = openvdb::Vec3R;
  const std::vector<Sphere>& spheres;
  size_t size() const { return spheres.size(); }
  void getPos(size_t n, openvdb::Vec3R& xyz) const {
    xyz = openvdb::Vec3R(spheres[n].centre.x(), spheres[n].centre.y(), spheres[n].centre.z());
  }
  void getPosRad(size_t n, openvdb::Vec3R& xyz, openvdb::Real& radius) const {
    getPos(n, xyz);
    radius = spheres[n].radius;
  }
};

// Points on the surface, uniform by area, each with its face normal.
std::vector<Sphere> surface_bumps(const SurfaceMesh& base, const PorosityParameters& p, RandomStream& random) {
  std::vector<double> cumulative_area(base.F.rows());
  double total = 0.0;
  for (Eigen::Index f = 0; f < base.F.rows(); ++f) {
    const auto [a, b, c] = triangle_corners(base, f);
    total += 0.5 * (b - a).cross(c - a).norm();
    cumulative_area[f] = total;
  }
  std::vector<Sphere> bumps;
  for (int i = 0; i < p.bump_count; ++i) {
    const double target = random.uniform() * total;
    const Eigen::Index f = std::lower_bound(cumulative_area.begin(), cumulative_area.end(), target) -
                           cumulative_area.begin();
    const auto [a, b, c] = triangle_corners(base, f);
    const double r1 = std::sqrt(random.uniform()), r2 = random.uniform();
    const Vec3 point = (1.0 - r1) * a + r1 * (1.0 - r2) * b + r1 * r2 * c;
    const Vec3 normal = (b - a).cross(c - a).normalized();
    const double radius = random.uniform(p.bump_radius_min, p.bump_radius_max);
    bumps.push_back({point - p.bump_depth * radius * normal, radius});
  }
  return bumps;
}

// Pore centres uniform in {sdf < -depth} by rejection from the bounding box.
std::vector<Sphere> core_pores(const openvdb::FloatGrid& base_sdf, const SurfaceMesh& base, int count,
                               double depth, const PorosityParameters& p, RandomStream& random) {
  const Vec3 low = base.V.colwise().minCoeff(), high = base.V.colwise().maxCoeff();
  openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sdf(base_sdf);
  std::vector<Sphere> pores;
  const long max_attempts = 1000L * count + 10000;
  for (long attempt = 0; attempt < max_attempts && static_cast<int>(pores.size()) < count; ++attempt) {
    const Vec3 centre(random.uniform(low.x(), high.x()), random.uniform(low.y(), high.y()),
                      random.uniform(low.z(), high.z()));
    const double radius = random.uniform(p.pore_radius_min, p.pore_radius_max);
    if (sdf.wsSample(openvdb::Vec3R(centre.x(), centre.y(), centre.z())) < -depth)
      pores.push_back({centre, radius});
  }
  return pores;
}

// Calls visit(ijk, value) for every active voxel, expanding active tiles.
template <class Visit>
void for_each_active_voxel(const openvdb::FloatGrid& grid, Visit visit) {
  for (auto it = grid.cbeginValueOn(); it; ++it) {
    if (it.isVoxelValue()) {
      visit(it.getCoord(), *it);
    } else {
      const openvdb::CoordBBox box = it.getBoundingBox();
      for (auto ijk = box.begin(); ijk; ++ijk) visit(*ijk, *it);
    }
  }
}

}  // namespace

void validate(const PorosityParameters& p) {
  check_porosity(p.bump_count >= 0, "bump_count", ">= 0");
  check_porosity(p.bump_radius_min > 0.0 && p.bump_radius_min <= p.bump_radius_max, "bump radii",
          "0 < bump_radius_min <= bump_radius_max");
  check_porosity(p.bump_depth >= 0.0 && p.bump_depth <= 1.0, "bump_depth", "in [0, 1]");
  check_porosity(p.core_porosity >= 0.0 && p.core_porosity <= 0.9, "core_porosity", "in [0, 0.9]");
  check_porosity(p.pore_radius_min > 0.0 && p.pore_radius_min <= p.pore_radius_max, "pore radii",
          "0 < pore_radius_min <= pore_radius_max");
  check_porosity(p.skin_thickness >= 0.0, "skin_thickness", ">= 0");
  check_porosity(p.voxel_size >= 0.0, "voxel_size", ">= 0 (0 picks the smallest radius / 1.5)");
  check_porosity(p.band_width >= 2.0, "band_width", ">= 2 voxels");
}

double voxel_size_for(const PorosityParameters& p) {
  if (p.voxel_size > 0.0) return p.voxel_size;
  return std::min(p.bump_radius_min, p.pore_radius_min) / kMinimumRadiusInVoxels;
}

int pore_count_for_porosity(double porosity, double centre_region_volume, double radius_min, double radius_max) {
  if (porosity <= 0.0 || centre_region_volume <= 0.0) return 0;
  const double mean_cube = radius_max > radius_min
                               ? (std::pow(radius_max, 4) - std::pow(radius_min, 4)) / (4.0 * (radius_max - radius_min))
                               : std::pow(radius_min, 3);
  const double mean_volume = 4.0 / 3.0 * std::numbers::pi * mean_cube;
  return static_cast<int>(std::ceil(-std::log(1.0 - porosity) * centre_region_volume / mean_volume));
}

openvdb::FloatGrid::Ptr signed_distance_field(const SurfaceMesh& mesh, double voxel_size, double band_width) {
  initialize_openvdb();
  std::vector<openvdb::Vec3s> points(mesh.V.rows());
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    points[v] = openvdb::Vec3s(float(mesh.V(v, 0)), float(mesh.V(v, 1)), float(mesh.V(v, 2)));
  std::vector<openvdb::Vec3I> triangles(mesh.F.rows());
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    triangles[f] = openvdb::Vec3I(mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2));
  const auto transform = openvdb::math::Transform::createLinearTransform(voxel_size);
  // On one thread: OpenVDB 10's sign correction of intersecting voxels reads neighbouring
  // leaves that other threads may be flipping, so on several threads a rare voxel's sign, and
  // with it the pores drawn against this field, changed from run to run (same seed, different
  // grain). Grains are generated in parallel with each other, so little is lost.
  openvdb::FloatGrid::Ptr grid;
  tbb::task_arena(1).execute([&] {
    grid = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(
        *transform, points, triangles, {}, float(band_width), std::numeric_limits<float>::max());
  });
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  return grid;
}

openvdb::FloatGrid::Ptr spheres_level_set(const std::vector<Sphere>& spheres, double voxel_size,
                                          double band_width, long* skipped) {
  initialize_openvdb();
  auto grid = openvdb::createLevelSet<openvdb::FloatGrid>(voxel_size, band_width);
  openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
  raster.setRmin(kMinimumRadiusInVoxels);
  raster.rasterizeSpheres(SphereList{spheres});
  raster.finalize(/*prune=*/true);
  // Counted here with the rasteriser's own test: its getMinCount() keeps only the count of
  // the last parallel chunk to finish.
  if (skipped)
    *skipped = std::count_if(spheres.begin(), spheres.end(), [&](const Sphere& s) {
      return s.radius / voxel_size < kMinimumRadiusInVoxels;
    });
  return grid;
}

double level_set_volume(const openvdb::FloatGrid& grid) { return openvdb::tools::levelSetVolume(grid); }

PorousLevelSet make_porous_level_set(const SurfaceMesh& base, const PorosityParameters& p, RandomStream& random) {
  validate(p);
  PorousLevelSet result;
  result.voxel_size = voxel_size_for(p);
  auto solid = signed_distance_field(base, result.voxel_size, p.band_width);

  // Centre region R and inner core, measured on the base field before any CSG.
  const double voxel_volume = std::pow(result.voxel_size, 3);
  const double centre_depth = p.skin_thickness + p.pore_radius_max;
  const double inner_depth = p.skin_thickness + 2.0 * p.pore_radius_max;
  std::vector<openvdb::Coord> inner_core;
  long centre_voxels = 0;
  for_each_active_voxel(*solid, [&](const openvdb::Coord& ijk, float value) {
    if (value < -centre_depth) ++centre_voxels;
    if (value < -inner_depth) inner_core.push_back(ijk);
  });
  result.centre_region_volume = centre_voxels * voxel_volume;
  result.inner_core_volume = static_cast<double>(inner_core.size()) * voxel_volume;

  const int pore_count = p.pore_count >= 0 ? p.pore_count
                                           : pore_count_for_porosity(p.core_porosity, result.centre_region_volume,
                                                                     p.pore_radius_min, p.pore_radius_max);
  const std::vector<Sphere> bumps = surface_bumps(base, p, random);
  const std::vector<Sphere> pores = core_pores(*solid, base, pore_count, centre_depth, p, random);
  result.bump_count = static_cast<int>(bumps.size());
  result.pore_count = static_cast<int>(pores.size());

  long skipped_bumps = 0, skipped_pores = 0;
  if (!bumps.empty()) {
    auto bump_grid = spheres_level_set(bumps, result.voxel_size, p.band_width, &skipped_bumps);
    openvdb::tools::csgUnion(*solid, *bump_grid);
  }
  result.solid_volume = level_set_volume(*solid);
  auto porous = solid->deepCopy();
  if (!pores.empty()) {
    auto pore_grid = spheres_level_set(pores, result.voxel_size, p.band_width, &skipped_pores);
    openvdb::tools::csgDifference(*porous, *pore_grid);
  }
  result.spheres_skipped = skipped_bumps + skipped_pores;
  result.porous_volume = level_set_volume(*porous);

  const auto accessor = porous->getConstAccessor();
  long void_voxels = 0;
  for (const openvdb::Coord& ijk : inner_core)
    if (accessor.getValue(ijk) > 0.0f) ++void_voxels;
  result.measured_core_porosity = inner_core.empty() ? 0.0 : double(void_voxels) / double(inner_core.size());
  result.grid = porous;
  return result;
}

}  // namespace rice::grains
