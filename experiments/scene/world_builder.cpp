// Building a scene's world; see world_builder.hpp.
#include "experiments/scene/world_builder.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "experiments/io/item_loop.hpp"
#include "experiments/scene/collider_grid.hpp"
#include "grains/absorption_table.hpp"
#include "grains/random_stream.hpp"
#include "grains/tet_quality.hpp"
#include "grains/water_content.hpp"
#include "xpbd/vertex_mass_floor.hpp"

namespace rice::experiments {
namespace {

using xpbd::Vec3;

/// Grain frame to world: p ↦ swell · R p + position.
grains::Vertices place(const grains::Vertices& V, double swell, const Eigen::Quaterniond& rotation, const Vec3& position) {
  return ((swell * V) * rotation.toRotationMatrix().transpose()).rowwise() + position.transpose();
}

/// The variants (each from its own seed, in parallel), then the instances, from one stream.
void make_grains(const SceneGrains& settings, const grains::GrainRecipe& recipe, World& world) {
  grains::RandomStream random(settings.seed);
  std::vector<std::uint64_t> seeds(settings.variants);
  for (std::uint64_t& seed : seeds) seed = random.child_seed();
  world.variants.resize(settings.variants);
  for_each_item("grain variants", settings.variants, [&](int i) {
    world.variants[i].grain = grains::make_grain(recipe, seeds[i], 1.0);
    world.variants[i].spheres = grains::fit_grain_collision_spheres(world.variants[i].grain);
  });
  world.instances = grains::make_instances(settings.count, settings.variants, recipe.cultivar, random);
  for (const GrainVariant& v : world.variants) {
    const grains::Vertices& V = v.grain.simulation.V;
    world.grain_length = std::max(world.grain_length, (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm());
    const double thickness = V.col(2).maxCoeff() - V.col(2).minCoeff();  // grains are made thickness along z
    world.grain_thickness = world.grain_thickness > 0.0 ? std::min(world.grain_thickness, thickness) : thickness;
  }
  world.grain_length *= recipe.cultivar.swell_max;
}

/// The container (the chawan's distance grid, or the plane z = 0 with normal +z), then the
/// scene's analytic colliders, then its meshes' distance grids, sampled now.
void add_colliders(const Scene& scene, World& world) {
  xpbd::Collider container;
  if (scene.container.kind == Container::kPlate) {
    container.shape = xpbd::ColliderShape::kHalfSpace;
  } else {
    container.shape = xpbd::ColliderShape::kDistanceGrid;
    container.grid = std::make_shared<const xpbd::DistanceGrid>(
        distance_grid_of(grains::make_chawan(world.bowl), scene.container.grid_spacing, 0.01));
  }
  container.static_friction = scene.effects.static_friction;
  container.dynamic_friction = scene.effects.dynamic_friction;
  std::vector<xpbd::Collider>& colliders = world.model.colliders;
  colliders.push_back(container);
  colliders.insert(colliders.end(), scene.colliders.begin(), scene.colliders.end());
  world.first_mesh_collider = static_cast<int>(colliders.size());
  for (const MeshCollider& m : scene.mesh_colliders) {
    xpbd::Collider c = m.collider;
    c.shape = xpbd::ColliderShape::kDistanceGrid;
    c.grid = std::make_shared<const xpbd::DistanceGrid>(distance_grid_of(m.mesh, m.grid_spacing, 0.01, m.hollow));
    colliders.push_back(std::move(c));
  }
}

/// A soft grain damped by the soak's τ: by XPBD, and by VBD when asked, as the paper's Rayleigh
/// damping of the constraints; by VBD by default as the strain-rate damping, which is convex
/// and adds no energy (a 100-grain VBD pour in the chawan: 41 grains awake at the end and
/// 2641 bond breaks with the constraints' damping, none awake and 1162 breaks with it).
int add_soft_grain(const Scene& scene, double tau, xpbd::Model& model, const xpbd::TetMesh& mesh, double density,
                   const xpbd::LameParameters& material, const xpbd::SphereSet& spheres) {
  const bool strain_rate = scene.solver.vertex_block_descent && scene.solver.vbd_strain_rate_damping;
  const int body = xpbd::add_soft_body(model, mesh, density, material, strain_rate ? 0.0 : tau, spheres,
                                       strain_rate ? tau : 0.0, scene.grains.elasticity);
  xpbd::floor_vertex_masses(model, body, scene.grains.vertex_mass_floor);
  return body;
}

/// Each grain's body at its build point moved to its parking place, asleep; its bond strength
/// the pull-off force in its own weights.
void add_bodies(const Scene& scene, World& world) {
  const int count = world.count();
  const auto material = xpbd::lame_from_young_poisson(scene.grains.young, scene.grains.poisson);
  xpbd::Model& model = world.model;
  world.rest_vertices.resize(count);
  for (int g = 0; g < count; ++g) {
    const GrainVariant& variant = world.variants[world.instances[g].variant];
    const double P = world.instances[g].swell;
    const Eigen::Quaterniond& R = world.instances[g].rotation;
    world.rest_vertices[g] = place(variant.grain.simulation.V, P, R, world.drops[g]);
    const xpbd::TetMesh mesh{world.rest_vertices[g].rowwise() + world.parking(g).transpose(), variant.grain.simulation.T};
    const xpbd::SphereSet spheres{place(variant.spheres.centres, P, R, world.drops[g] + world.parking(g)),
                                  P * variant.spheres.radii};
    const double density = variant.grain.simulation_density;
    const int b = scene.grains.body == xpbd::BodyKind::kRigid
                      ? xpbd::add_rigid_body(model, mesh, density, spheres)
                      : add_soft_grain(scene, world.rayleigh_time, model, mesh, density, material, spheres);
    const double mass = density * grains::total_volume({mesh.V, mesh.T});
    model.bodies[b].bond_strength = scene.effects.cohesion ? world.pull_off_in_weights * mass * model.gravity.norm() : 0.0;
    model.bodies[b].asleep = true;  // parked until its emitter releases it
  }
  world.initial_centre.resize(count);
  for (int g = 0; g < count; ++g) world.initial_centre[g] = world.centre(g) - world.parking(g);
  for (const xpbd::RigidBody& rigid : model.rigid_bodies) world.initial_orientation.push_back(rigid.q());
}

}  // namespace

World build_world(const Scene& scene, Emitter& emitter) {
  World world;
  world.bowl = grains::scaled({}, scene.container.scale);
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name(scene.grains.cultivar);
  recipe.simulation.min_vertices = scene.grains.min_vertices;
  recipe.simulation.max_vertices = scene.grains.max_vertices;
  make_grains(scene.grains, recipe, world);
  add_colliders(scene, world);
  emitter.lay_out(world);

  const grains::WaterContentModel water(grains::read_absorption_table(grains::default_absorption_table()));
  const double stickiness = std::isnan(scene.grains.stickiness) ? recipe.cultivar.stickiness : scene.grains.stickiness;
  world.pull_off_in_weights = water.cohesion_ratio(stickiness, scene.grains.soak_minutes, scene.grains.soak_temperature);
  world.rayleigh_time =
      scene.effects.damping ? water.beta(scene.grains.soak_minutes, scene.grains.soak_temperature) : 0.0;
  world.model.contact.static_friction = scene.effects.static_friction;
  world.model.contact.dynamic_friction = scene.effects.dynamic_friction;
  world.model.contact.cohesion = scene.effects.cohesion;
  if (!std::isnan(scene.grains.heal_time)) world.model.contact.bond_heal_time = scene.grains.heal_time;
  world.model.contact.radius_interval = scene.solver.radius_interval;
  world.model.sleep.enabled = scene.effects.sleeping;
  world.model.sleep.speed = scene.effects.sleep_speed;
  world.model.sleep.steps = scene.effects.sleep_frames;
  add_bodies(scene, world);
  return world;
}

}  // namespace rice::experiments
