// The fill ([emitter] kind = "fill"): the grains fill a hollow mesh collider (a mould) in
// rounds `round_s` apart. Each grain is built along the world's axes (turned end over end or
// not) at a point of a lattice of the largest grain's box inside the mould (mould_fill.hpp);
// each round puts grains at the lattice points no grain is near, lowest first, and they settle
// before the next. Rounds stop when the mould is removed; grains without room stay parked and
// out of every measure.
#pragma once

#include "experiments/scene/emitter.hpp"
#include "experiments/scene/scene.hpp"

namespace rice::experiments {

class FillEmitter : public Emitter {
 public:
  explicit FillEmitter(const Scene& scene);

  /// Throws std::invalid_argument when not one grain fits in the mould.
  void lay_out(World& world) override;
  void emit(World& world, double time) override;
  /// Also says on the terminal how many grains found no room.
  void report(const World& world, RunInfoEntries& info) const override;

 private:
  const xpbd::Collider& mould(const World& world) const;

  int mould_;  ///< index among the scene's mesh colliders
  double round_seconds_, swell_max_;
  xpbd::Vec3 cell_ = xpbd::Vec3::Zero();
  std::vector<xpbd::Vec3> lattice_;
  double next_round_ = 0.0;
  int rounds_ = 0;
};

}  // namespace rice::experiments
