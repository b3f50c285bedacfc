// The clump; see clump_emitter.hpp.
#include "experiments/scene/clump_emitter.hpp"

#include "experiments/io/csv_table.hpp"

namespace rice::experiments {

void ClumpEmitter::report(const World& world, RunInfoEntries& info) const {
  info.push_back({"emitter", "clump"});
  info.push_back({"spout_height_m", cell(settings_.height)});
  info.push_back({"spout_radius_m", cell(radius_)});
  info.push_back({"grains_per_layer", cell(per_layer_)});
  info.push_back({"grains_placed", cell(world.released)});
}

}  // namespace rice::experiments
