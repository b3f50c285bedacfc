// A scene's own checks; see scene.hpp.
#include "experiments/scene/scene.hpp"

#include <algorithm>
#include <stdexcept>

#include "experiments/io/csv_table.hpp"
#include "experiments/scene/scene_keys.hpp"
#include "grains/cultivar.hpp"

namespace rice::experiments {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("scene: " + what);
}

void validate_grains_and_solver(const Scene& s) {
  grains::cultivar_by_name(s.grains.cultivar);  // throws, listing the names
  check(scene_key("grains", "count"), s.grains.count);
  check(scene_key("grains", "variants"), s.grains.variants);
  check(scene_key("grains", "young_pa"), s.grains.young);
  check(scene_key("grains", "min_vertices"), s.grains.min_vertices);
  check(scene_key("grains", "max_vertices"), s.grains.max_vertices);
  require(s.grains.min_vertices <= s.grains.max_vertices,
          "need [grains] min_vertices <= max_vertices, got " + cell(s.grains.min_vertices) + " and " +
              cell(s.grains.max_vertices));
  check(scene_key("grains", "vertex_mass_floor"), s.grains.vertex_mass_floor);
  check(scene_key("grains", "poisson"), s.grains.poisson);
  require(s.grains.elasticity != xpbd::TetMaterial::kCorotated || s.grains.poisson > 0.0,
          "[grains] elasticity = 'corotated' needs poisson > 0 (its volume term's stiffness is the Lamé "
          "lambda), got " + cell(s.grains.poisson));
  check(scene_key("grains", "soak_minutes"), s.grains.soak_minutes);
  check(scene_key("grains", "soak_temperature_c"), s.grains.soak_temperature);
  if (!std::isnan(s.grains.stickiness)) check(scene_key("grains", "stickiness"), s.grains.stickiness);
  if (!std::isnan(s.grains.heal_time)) check(scene_key("grains", "heal_s"), s.grains.heal_time);
  check(scene_key("solver", "fps"), s.solver.fps);
  check(scene_key("solver", "frames"), s.solver.frames);
  check(scene_key("solver", "substeps"), s.solver.substeps);
  check(scene_key("solver", "iterations"), s.solver.iterations);
  check(scene_key("solver", "radius_interval_s"), s.solver.radius_interval);
  check(scene_key("solver", "checkpoint_every"), s.solver.checkpoint_every);
  require(!s.solver.vertex_block_descent || s.grains.body == xpbd::BodyKind::kSoft,
          "[solver] method = 'vbd' needs soft grains");
}

void validate_container_emitter_effects(const Scene& s) {
  check(scene_key("container", "grid_spacing_m"), s.container.grid_spacing);
  check(scene_key("container", "scale"), s.container.scale);
  check(scene_key("emitter", "height_m"), s.emitter.height);
  check(scene_key("emitter", "radius_m"), s.emitter.radius);
  if (s.emitter.kind == EmitterKind::kSpout) check(scene_key("emitter", "seconds"), s.emitter.seconds);
  check(scene_key("emitter", "round_s"), s.emitter.round_seconds);
  require(s.emitter.kind != EmitterKind::kFill ||
              (s.emitter.mould >= 0 && s.emitter.mould < static_cast<int>(s.mesh_colliders.size()) &&
               s.mesh_colliders[s.emitter.mould].hollow),
          "the mould to fill must be a hollow mesh collider");
  check(scene_key("effects", "static_friction"), s.effects.static_friction);
  check(scene_key("effects", "dynamic_friction"), s.effects.dynamic_friction);
  require(s.effects.dynamic_friction <= s.effects.static_friction,
          "need dynamic_friction <= static_friction, got " + cell(s.effects.dynamic_friction) + " and " +
              cell(s.effects.static_friction));
}

void validate_colliders(const Scene& s) {
  for (size_t c = 0; c < s.colliders.size(); ++c) {
    require(s.colliders[c].shape != xpbd::ColliderShape::kDistanceGrid, "scene colliders are analytic shapes");
    xpbd::validate(s.colliders[c], static_cast<int>(c) + 1);  // 0 is the container
  }
  for (const MeshCollider& m : s.mesh_colliders) {
    require(m.mesh.F.rows() > 0 && m.mesh.V.allFinite(), "a mesh collider needs triangles and finite vertices");
    check(scene_key("colliders", "grid_spacing_m"), m.grid_spacing);
  }
}

}  // namespace

void validate(const Scene& scene) {
  validate_grains_and_solver(scene);
  validate_container_emitter_effects(scene);
  validate_colliders(scene);
}

int substeps_per_frame(const Scene& scene) {
  if (scene.solver.substeps > 0) return scene.solver.substeps;
  if (scene.grains.body == xpbd::BodyKind::kRigid) return 80;
  return scene.grains.elasticity == xpbd::TetMaterial::kCorotated ? 160 : 480;
}

bool any_collider(const Scene& scene, const std::function<bool(const xpbd::Collider&)>& property) {
  return std::any_of(scene.colliders.begin(), scene.colliders.end(), property) ||
         std::any_of(scene.mesh_colliders.begin(), scene.mesh_colliders.end(),
                     [&](const MeshCollider& m) { return property(m.collider); });
}

}  // namespace rice::experiments
