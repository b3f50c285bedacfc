// Grain pipeline and instancing (see grain_generator.hpp).
#include "grains/grain_generator.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "grains/level_set_mesh.hpp"
#include "grains/mesh_topology.hpp"
#include "grains/surface_measures.hpp"
#include "grains/tet_quality.hpp"

namespace rice::grains {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Uniform random rotation (Shoemake, "Uniform random rotations", Graphics Gems III, 1992).
Eigen::Quaterniond uniform_rotation(RandomStream& random) {
  const double u1 = random.uniform(), u2 = random.uniform(), u3 = random.uniform();
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1), two_pi = 2.0 * std::numbers::pi;
  return Eigen::Quaterniond(b * std::cos(two_pi * u3), a * std::sin(two_pi * u2), a * std::cos(two_pi * u2),
                            b * std::sin(two_pi * u3));
}

}  // namespace

void validate(const GrainRecipe& recipe) {
  validate(recipe.cultivar);
  validate(recipe.porosity);
  validate(recipe.simulation);
  if (recipe.cage) validate(*recipe.cage);
  if (!(recipe.mesh_adaptivity >= 0.0 && recipe.mesh_adaptivity <= 1.0))
    throw std::invalid_argument("mesh adaptivity must be in [0, 1]");
  if (!(recipe.density > 0.0)) throw std::invalid_argument("density must be positive");
  if (recipe.base_mesh) {
    require_closed_manifold(*recipe.base_mesh, "base mesh");
    if (!(enclosed_volume(*recipe.base_mesh) > 0.0))
      throw std::invalid_argument("base mesh: its faces point inwards (negative enclosed volume)");
  }
}

Grain make_grain(const GrainRecipe& recipe, std::uint64_t seed, std::optional<double> swell) {
  RandomStream random(seed);
  Grain grain;
  grain.shape = sample_grain_shape(recipe.cultivar, random);
  if (swell) grain.shape.swell = *swell;
  const SurfaceMesh base = recipe.base_mesh ? *recipe.base_mesh : make_base_shape(grain.shape, recipe.base_resolution);
  if (recipe.base_mesh) {
    const Vec3 extent = bounding_box_extent(base.V);
    grain.shape.length = extent.x();
    grain.shape.width = extent.y();
    grain.shape.thickness = extent.z();
  }

  auto start = std::chrono::steady_clock::now();
  grain.level_set = make_porous_level_set(base, recipe.porosity, random);
  grain.timings.level_set = seconds_since(start);

  start = std::chrono::steady_clock::now();
  grain.render = level_set_to_mesh(*grain.level_set.grid, recipe.mesh_adaptivity);
  grain.timings.render_mesh = seconds_since(start);

  start = std::chrono::steady_clock::now();
  // The cage draws no random number, so the streams after it match Mesh_3's grains.
  const std::uint64_t mesh_seed = random.child_seed();
  if (recipe.cage) {
    Vertices enclosed(base.V.rows() + grain.render.V.rows(), 3);
    enclosed << base.V, grain.render.V;  // the porous render surface bulges past the base in places
    grain.simulation = make_template_cage(enclosed, *recipe.cage);
  } else {
    grain.simulation = make_simulation_mesh(base, recipe.simulation, mesh_seed);
  }
  grain.caged = recipe.cage.has_value();
  grain.timings.simulation_mesh = seconds_since(start);

  start = std::chrono::steady_clock::now();
  grain.embedding = embed_points(grain.render.V, grain.simulation);
  grain.timings.embedding = seconds_since(start);

  // Eq. 2, [x, y, z] = P [r, s, t]: a uniform scale, which leaves the embedding unchanged.
  grain.render.V *= grain.shape.swell;
  grain.simulation.V *= grain.shape.swell;
  grain.base = base;
  grain.base.V *= grain.shape.swell;
  grain.simulation_density = recipe.density * enclosed_volume(grain.render) / total_volume(grain.simulation);
  return grain;
}

std::vector<GrainInstance> make_instances(int count, int variants, const Cultivar& cultivar, RandomStream& random) {
  if (count < 0 || variants < 1) throw std::invalid_argument("instances: need count >= 0 and variants >= 1");
  std::vector<GrainInstance> instances(count);
  for (GrainInstance& instance : instances) {
    instance.variant = std::min(variants - 1, static_cast<int>(random.uniform() * variants));
    instance.swell = random.uniform(cultivar.swell_min, cultivar.swell_max);
    instance.rotation = uniform_rotation(random);
  }
  return instances;
}

CollisionSpheres fit_grain_collision_spheres(const Grain& grain) {
  return grain.caged ? fit_collision_spheres(grain.base) : fit_collision_spheres(grain.simulation);
}

}  // namespace rice::grains
