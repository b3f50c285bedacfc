// The fill; see fill_emitter.hpp.
#include "experiments/scene/fill_emitter.hpp"

#include <array>
#include <cstdio>
#include <stdexcept>

#include "experiments/io/csv_table.hpp"
#include "experiments/scene/mould_fill.hpp"
#include "grains/cultivar.hpp"

namespace rice::experiments {

FillEmitter::FillEmitter(const Scene& scene)
    : mould_(scene.emitter.mould),
      round_seconds_(scene.emitter.round_seconds),
      swell_max_(grains::cultivar_by_name(scene.grains.cultivar).swell_max) {}

const xpbd::Collider& FillEmitter::mould(const World& world) const {
  return world.model.colliders[world.first_mesh_collider + mould_];
}

void FillEmitter::lay_out(World& world) {
  xpbd::Vec3 box = xpbd::Vec3::Zero();
  for (const GrainVariant& v : world.variants)
    box = box.cwiseMax((v.grain.simulation.V.colwise().maxCoeff() - v.grain.simulation.V.colwise().minCoeff()).transpose());
  cell_ = 1.05 * swell_max_ * box;
  lattice_ = mould_lattice(mould(world), cell_);
  if (lattice_.empty()) throw std::invalid_argument("fill: not one grain fits in the mould");
  // Each grain is built at a lattice point (parked apart from the others: a row of parking
  // places is one lattice's worth) and moved to its own point when released.
  world.drops.clear();
  for (int g = 0; g < world.count(); ++g) world.drops.push_back(lattice_[g % lattice_.size()]);
  const std::array<Eigen::Quaterniond, 4> turns{
      Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0), Eigen::Quaterniond(0.0, 0.0, 1.0, 0.0),
      Eigen::Quaterniond(0.0, 0.0, 0.0, 1.0)};
  for (int g = 0; g < world.count(); ++g) world.instances[g].rotation = turns[g % 4];
  world.parking_row = static_cast<int>(lattice_.size());
}

void FillEmitter::emit(World& world, double time) {
  if (world.released == world.count() || time < next_round_ - 1e-9 || time >= mould(world).removal_time) return;
  // A round: grains at the free lattice points, lowest first.
  for (const xpbd::Vec3& spot : free_points(lattice_, world.released_centres(), cell_.maxCoeff())) {
    if (world.released == world.count()) break;
    world.release(world.released, spot - world.drops[world.released]);
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

}  // namespace rice::experiments
