// The fill ([emitter] kind = "fill"): grains are dropped into a hollow mesh collider (a mould)
// the way a cook drops rice in by the handful, in rounds `round_s` apart for `seconds`. Each
// grain keeps the random orientation it was made with (uniform on SO(3)). A round drops grains,
// lowest first, at the release points no grain is near: the points of a lattice inside the
// mould (mould_fill.hpp) whose cubes are 1.1 grain lengths L across, the lattice shifted by a
// random fraction of a cube in x and y each round and each point moved by a random offset of
// up to L/20 per axis, so that no two grains a round releases can touch (their centres stay L
// apart) and no two rounds release on the same lattice (with one lattice shifted only by the
// offsets, the grains stacked in columns, seen from the top of the bunny's pile). The grains
// leave moving down at 1 m/s, as from a hand 5 cm above, fall, tumble and settle; with rounds a
// few hundredths of a second apart the fill is a steady rain that frees the top points again as
// fast as the grains fall (released at rest, the bunny's mould took 1981 grains in 3.5 s; at
// 1 m/s, 2502). (An earlier fill built the grains along the axes at the points of a lattice of
// their boxes: it packed denser per round, but the moulded shapes showed the lattice, which no
// cook's fill does.) Rounds stop when the mould is removed; grains without room stay parked and
// out of every measure.
#pragma once

#include "experiments/scene/emitter.hpp"
#include "grains/random_stream.hpp"
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
  /// The random stream, the next round's time and the rounds so far.
  void save_state(xpbd::StateWriter& out) const override;
  void load_state(xpbd::StateReader& in) override;

 private:
  const xpbd::Collider& mould(const World& world) const;

  int mould_;  ///< index among the scene's mesh colliders
  double round_seconds_, seconds_;  ///< between rounds, and until the last
  grains::RandomStream random_;  ///< the lattice's shifts and the release points' offsets
  double clearance_ = 0.0;       ///< L: no grain centre nearer a release point [m]
  std::vector<xpbd::Vec3> lattice_;
  double next_round_ = 0.0;
  int rounds_ = 0;
};

}  // namespace rice::experiments
