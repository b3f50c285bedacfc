// The spout ([emitter] kind = "spout"): grains leave a round opening above the container as a
// stream, layer by layer, evenly over `seconds`. A layer is the points of a square lattice, a
// grain length and a little apart, inside the opening; each grain waits parked until its
// layer leaves. The chawan's opening is 0.6 of its inner radius wide, the plate's one grain.
#pragma once

#include "experiments/scene/emitter.hpp"
#include "experiments/scene/scene.hpp"

namespace rice::experiments {

class SpoutEmitter : public Emitter {
 public:
  SpoutEmitter(const SceneEmitter& settings, const SceneContainer& container);

  /// Throws std::invalid_argument when a layer would leave before the one below it has fallen
  /// clear of the opening (grains would be released inside each other).
  void lay_out(World& world) override;
  void emit(World& world, double time) override;
  void report(const World& world, RunInfoEntries& info) const override;

 protected:
  /// The layout without the spout's timing check (the clump's).
  void lay_out_layers(World& world);
  /// How many grains have left by `time`.
  virtual int due(const World& world, double time) const;
  /// A heap that grew up to the opening (sticky grains build columns) would have new grains
  /// released inside it, so the opening rises to keep a grain length and a half above the top
  /// of the grains that have landed (slower than 0.1 m/s; a grain falls faster 10 ms after its
  /// release, and layers leave further apart than that).
  double lift(const World& world) const;

  SceneEmitter settings_;
  bool plate_;
  double radius_ = 0.0;  ///< of the opening [m]
  int per_layer_ = 0, layers_ = 0;
};

}  // namespace rice::experiments
