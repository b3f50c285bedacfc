// What a renderer or a plot needs to redraw a run (`rice render --run`, pile.png), written
// before the first frame: grains.csv (each grain's variant, swell P, rotation R, build point
// and initial centre c₀, so that a frame's pose (c, q) puts render vertex p at
// c + q (drop + P R p − c₀)), the variants' render meshes (variants/variant_k.ply), for soft
// grains their simulation meshes too (variants/variant_k.mesh, MEDIT: a frame's vertices are
// theirs, deformed, and carry the render mesh through its embedding), and in a chawan its mesh
// (chawan.obj) and the inside wall's profile (bowl_outline.csv).
#pragma once

#include <filesystem>

#include "experiments/scene/observer.hpp"

namespace rice::experiments {

class SceneGeometryObserver : public Observer {
 public:
  SceneGeometryObserver(const std::filesystem::path& folder, bool chawan) : folder_(folder), chawan_(chawan) {}
  void begin(const World& world) override;

 private:
  std::filesystem::path folder_;
  bool chawan_;
};

}  // namespace rice::experiments
