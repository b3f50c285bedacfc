// The fill; see fill_emitter.hpp.
#include "experiments/scene/fill_emitter.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "experiments/io/csv_table.hpp"
#include "experiments/scene/mould_fill.hpp"

namespace rice::experiments {

namespace {
// Grains leave the hand moving down at the speed of a fall of 5 cm, √(2 g 0.05 m): they clear
// their release points in a few milliseconds, and the next round finds them free.
constexpr double kDropSpeed = 0.99;  // [m/s]
constexpr double kCellInGrainLengths = 1.1;  // the lattice's cube side; offsets up to (1.1 − 1)/2 L
}  // namespace

// The release offsets' stream is its own, seeded from the scene's seed, so they change with it
// and the grains' shapes do not change with the fill.
FillEmitter::FillEmitter(const Scene& scene)
    : mould_(scene.emitter.mould),
      round_seconds_(scene.emitter.round_seconds),
      seconds_(scene.emitter.seconds),
      random_(scene.grains.seed ^ 0xF111ULL) {}

const xpbd::Collider& FillEmitter::mould(const World& world) const {
  return world.model.colliders[world.first_mesh_collider + mould_];
}

void FillEmitter::lay_out(World& world) {
  clearance_ = world.grain_length;
  lattice_ = mould_lattice(mould(world), xpbd::Vec3::Constant(kCellInGrainLengths * clearance_));
  if (lattice_.empty()) throw std::invalid_argument("fill: not one grain fits in the mould");
  // Each grain is built at a lattice point (parked apart from the others: a row of parking
  // places is one lattice's worth) and moved to its release point when released.
  world.drops.clear();
  for (int g = 0; g < world.count(); ++g) world.drops.push_back(lattice_[g % lattice_.size()]);
  world.parking_row = static_cast<int>(lattice_.size());
}

void FillEmitter::emit(World& world, double time) {
  if (world.released == world.count() || time < next_round_ - 1e-9 || time >= std::min(seconds_, mould(world).removal_time))
    return;
  // A round: the lattice shifted by a random fraction of a cell in x and y (with one lattice for
  // every round, grains dropped at its points stacked in columns that showed in the moulded
  // shapes), its points moved by this round's offsets, those no grain is near, lowest first.
  const xpbd::Vec3 shift(random_.uniform(0.0, 1.0), random_.uniform(0.0, 1.0), 0.0);
  const double offset = 0.5 * (kCellInGrainLengths - 1.0) * clearance_;
  std::vector<xpbd::Vec3> points =
      mould_lattice(mould(world), xpbd::Vec3::Constant(kCellInGrainLengths * clearance_), shift);
  for (xpbd::Vec3& p : points)
    p += xpbd::Vec3(random_.uniform(-offset, offset), random_.uniform(-offset, offset), random_.uniform(-offset, offset));
  for (const xpbd::Vec3& spot : free_points(points, world.released_centres(), clearance_)) {
    if (world.released == world.count()) break;
    world.release(world.released, spot - world.drops[world.released], xpbd::Vec3(0.0, 0.0, -kDropSpeed));
    ++world.released;
  }
  next_round_ = time + round_seconds_;
  ++rounds_;
}

void FillEmitter::report(const World& world, RunInfoEntries& info) const {
  if (world.released < world.count())
    std::printf("fill: %d of %d grains found no room in the mould (they stay parked, out of the measures)\n",
                world.count() - world.released, world.count());
  info.push_back({"emitter", "fill"});
  info.push_back({"fill_rounds", cell(rounds_)});
  info.push_back({"grains_per_layer", cell(static_cast<long>(lattice_.size()))});
  info.push_back({"grains_placed", cell(world.released)});
}

void FillEmitter::save_state(xpbd::StateWriter& out) const { out(random_.state(), next_round_, rounds_); }

void FillEmitter::load_state(xpbd::StateReader& in) {
  std::string random;
  in(random, next_round_, rounds_);
  random_.set_state(random);
}

}  // namespace rice::experiments
