// What a renderer or a plot needs to redraw a run (`rice render --run`, pile.png), written
// before the first frame: grains.csv (each grain's variant, swell P, rotation R, build point
// and initial centre c₀, so that a frame's pose (c, q) puts render vertex p at
// c + q (drop + P R p − c₀)), the variants' render meshes (variants/variant_k.ply), for soft
// grains their simulation meshes too (variants/variant_k.mesh, MEDIT: a frame's vertices are
// theirs, deformed, and carry the render mesh through its embedding), and in a chawan its mesh
// (chawan.obj) and the inside wall's profile (bowl_outline.csv); the other colliders as they
// are drawn (colliders/, collider_drawing.hpp).
#pragma once

#include <filesystem>
#include <utility>
#include <vector>

#include "experiments/render/collider_drawing.hpp"
#include "experiments/scene/observer.hpp"
#include "experiments/scene/scene.hpp"

namespace rice::experiments {

/// The scene's colliders beside the container as drawn, in the solver's order: analytic, then
/// meshes.
std::vector<ColliderDrawing> collider_drawings(const Scene& scene);

class SceneGeometryObserver : public Observer {
 public:
  SceneGeometryObserver(const std::filesystem::path& folder, bool chawan, std::vector<ColliderDrawing> colliders)
      : folder_(folder), chawan_(chawan), colliders_(std::move(colliders)) {}
  void begin(const World& world) override;

 private:
  std::filesystem::path folder_;
  bool chawan_;
  std::vector<ColliderDrawing> colliders_;
};

}  // namespace rice::experiments
