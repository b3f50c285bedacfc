// The parts of a scene run; see scene_parts.hpp.
#include "experiments/scene/scene_parts.hpp"

#include <cmath>

#include "experiments/scene/carried_observer.hpp"
#include "experiments/scene/clump_emitter.hpp"
#include "experiments/scene/fill_emitter.hpp"
#include "experiments/scene/frames_observer.hpp"
#include "experiments/scene/impact_observer.hpp"
#include "experiments/scene/paraview_observer.hpp"
#include "experiments/scene/pile_observer.hpp"
#include "experiments/scene/render_mesh_observer.hpp"
#include "experiments/scene/scene_geometry_observer.hpp"
#include "experiments/scene/section_observer.hpp"
#include "experiments/scene/spout_emitter.hpp"
#include "experiments/scene/stats_observer.hpp"
#include "experiments/scene/yield_observer.hpp"

namespace rice::experiments {

std::unique_ptr<Emitter> make_emitter(const Scene& scene) {
  switch (scene.emitter.kind) {
    case EmitterKind::kSpout: return std::make_unique<SpoutEmitter>(scene.emitter, scene.container);
    case EmitterKind::kClump: return std::make_unique<ClumpEmitter>(scene.emitter, scene.container);
    case EmitterKind::kFill: return std::make_unique<FillEmitter>(scene);
  }
  return nullptr;
}

namespace {

/// The lowest point of a mesh collider at a time [m].
double lowest_point(const MeshCollider& mould, double time) {
  const xpbd::ColliderKeyframe pose = xpbd::collider_pose(mould.collider, time);
  double lowest = INFINITY;
  for (int v = 0; v < mould.mesh.V.rows(); ++v)
    lowest = std::min(lowest, xpbd::to_world(pose, mould.mesh.V.row(v).transpose()).z());
  return lowest;
}

}  // namespace

std::optional<double> drop_time(const Scene& scene) {
  if (scene.emitter.kind == EmitterKind::kClump) return 0.0;
  if (scene.emitter.kind != EmitterKind::kFill) return std::nullopt;
  // A mould held above the ground (a cup) drops its grains when it is taken away.
  const MeshCollider& mould = scene.mesh_colliders[scene.emitter.mould];
  const double removal = mould.collider.removal_time;
  if (!std::isfinite(removal)) return std::nullopt;
  // Its lowest point then more than 5 mm (about a grain) above the ground, z = 0.
  return lowest_point(mould, removal) > 5e-3 ? std::optional(removal) : std::nullopt;
}

std::vector<std::unique_ptr<Observer>> make_observers(const Scene& scene, const std::filesystem::path& folder) {
  std::vector<std::unique_ptr<Observer>> observers;
  observers.push_back(std::make_unique<SceneGeometryObserver>(folder, scene.container.kind == Container::kChawan,
                                                              collider_drawings(scene)));
  observers.push_back(std::make_unique<StatsObserver>(folder));
  observers.push_back(std::make_unique<FramesObserver>(folder));
  if (scene.effects.render_meshes) observers.push_back(std::make_unique<RenderMeshObserver>(folder));
  if (scene.effects.paraview) observers.push_back(std::make_unique<ParaviewObserver>(folder, scene.solver.fps));
  observers.push_back(std::make_unique<PileObserver>(folder, scene));
  if (const std::optional<double> drop = drop_time(scene)) observers.push_back(std::make_unique<ImpactObserver>(*drop));
  observers.push_back(std::make_unique<SectionObserver>(folder, scene));
  if (any_collider_yields(scene)) observers.push_back(std::make_unique<YieldObserver>(folder));
  if (any_collider(scene, moves)) observers.push_back(std::make_unique<CarriedObserver>());
  return observers;
}

}  // namespace rice::experiments
