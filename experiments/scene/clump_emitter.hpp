// The clump ([emitter] kind = "clump"): the spout's layers all leave at once, stacked a
// little over a grain length apart, so the grains drop together as one block (paper Fig. 10's
// drop, the press).
#pragma once

#include "experiments/scene/spout_emitter.hpp"

namespace rice::experiments {

class ClumpEmitter : public SpoutEmitter {
 public:
  using SpoutEmitter::SpoutEmitter;

  void lay_out(World& world) override { lay_out_layers(world); }
  void report(const World& world, RunInfoEntries& info) const override;

 protected:
  int due(const World& world, double) const override { return world.count(); }
};

}  // namespace rice::experiments
