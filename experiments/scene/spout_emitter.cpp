// The spout; see spout_emitter.hpp.
#include "experiments/scene/spout_emitter.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "experiments/io/csv_table.hpp"

namespace rice::experiments {
namespace {

using xpbd::Vec3;

/// Spout positions: a square lattice of `cell` inside a circle of `radius` at height
/// `bottom`; grain k goes to point k mod n of layer k / n.
std::vector<Vec3> spout_positions(int count, double cell, double radius, double bottom, int* per_layer) {
  std::vector<Vec3> layer;
  const int n = static_cast<int>(std::floor(radius / cell));
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      if (std::hypot(i * cell, j * cell) <= radius) layer.emplace_back(i * cell, j * cell, 0.0);
  if (layer.empty()) throw std::invalid_argument("spout: the opening is narrower than one grain");
  std::vector<Vec3> positions;
  for (int k = 0; k < count; ++k) positions.push_back(layer[k % layer.size()] + Vec3(0.0, 0.0, bottom));
  *per_layer = static_cast<int>(layer.size());
  return positions;
}

}  // namespace

SpoutEmitter::SpoutEmitter(const SceneEmitter& settings, const SceneContainer& container)
    : settings_(settings), plate_(container.kind == Container::kPlate) {}

void SpoutEmitter::lay_out_layers(World& world) {
  const double inner_radius = world.bowl.rim_radius - world.bowl.wall_thickness;
  const double longest = world.grain_length;
  radius_ = settings_.radius > 0.0 ? settings_.radius : plate_ ? 1.1 * longest : 0.6 * inner_radius - longest;
  world.drops = spout_positions(world.count(), 1.05 * longest, radius_,
                                settings_.height + (plate_ ? 0.0 : world.bowl.height), &per_layer_);
  layers_ = (world.count() + per_layer_ - 1) / per_layer_;
  world.parking_row = per_layer_;
}

void SpoutEmitter::lay_out(World& world) {
  lay_out_layers(world);
  // A layer must have fallen clear of the opening, 1.05 grain lengths from rest, before the
  // next leaves: else grains are released inside each other.
  const double clear_seconds = std::sqrt(2.0 * 1.05 * world.grain_length / 9.81);
  if (layers_ > 1 && settings_.seconds / layers_ < clear_seconds)
    throw std::invalid_argument("spout: " + std::to_string(layers_) + " layers of " + std::to_string(per_layer_) +
                                " grains leave " + fixed(1e3 * settings_.seconds / layers_, 1) +
                                " ms apart, sooner than one falls clear of the next (" + fixed(1e3 * clear_seconds, 1) +
                                " ms): raise [emitter] seconds to at least " + fixed(layers_ * clear_seconds, 2));
}

int SpoutEmitter::due(const World& world, double time) const {
  return std::min(world.count(),
                  per_layer_ * (1 + static_cast<int>(std::floor(time / settings_.seconds * layers_))));
}

double SpoutEmitter::lift(const World& world) const {
  double top = -INFINITY;
  for (int g = 0; g < world.released; ++g)
    if (world.speed(g) < 0.1) top = std::max(top, world.centre(g).z());
  return std::max(0.0, top + 1.5 * world.grain_length - world.drops.front().z());
}

void SpoutEmitter::emit(World& world, double time) {
  const int grains_due = due(world, time);
  if (world.released >= grains_due) return;
  // Layers due in the same frame (long frames) leave stacked a cell apart.
  const double up = lift(world);
  const int first_layer = world.released / per_layer_;
  for (; world.released < grains_due; ++world.released)
    world.release(world.released,
                  Vec3(0.0, 0.0, up + 1.05 * world.grain_length * (world.released / per_layer_ - first_layer)));
}

void SpoutEmitter::report(const World& world, RunInfoEntries& info) const {
  info.push_back({"emitter", "spout"});
  info.push_back({"pour_seconds", cell(settings_.seconds)});
  info.push_back({"spout_height_m", cell(settings_.height)});
  info.push_back({"spout_radius_m", cell(radius_)});
  info.push_back({"grains_per_layer", cell(per_layer_)});
  info.push_back({"grains_placed", cell(world.released)});
}

}  // namespace rice::experiments
