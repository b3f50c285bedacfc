// yield.csv of a run with colliders that give way past a force ([[colliders]] force_limit_n):
// a row per frame and yielding collider, with how far it stands back from its keyframed pose
// along its yield axis (and the axis), and the mean force the grains put on it along that axis
// over the last broad-phase interval. Listed only for scenes with such a collider.
// `rice render --run` draws each collider where this says it was.
#pragma once

#include <filesystem>

#include "experiments/io/csv_table.hpp"
#include "experiments/scene/observer.hpp"
#include "experiments/scene/scene.hpp"

namespace rice::experiments {

/// Whether any of the scene's colliders yields (then a run writes yield.csv).
bool any_collider_yields(const Scene& scene);

class YieldObserver : public Observer {
 public:
  explicit YieldObserver(const std::filesystem::path& folder);
  void observe(const World& world, const Stepper& stepper, int frame, double wall_seconds) override;
  /// The rows so far.
  void save_state(xpbd::StateWriter& out) const override;
  void load_state(xpbd::StateReader& in) override;

 private:
  std::filesystem::path folder_;
  CsvTable rows_;
};

}  // namespace rice::experiments
