// stats.csv of a run, a row per frame, written after each: wall time, awake grains, candidate
// pairs, contacts, bonds (holding and broken so far), the deepest penetration, kinetic energy,
// the top grain centre, and the frame's time in broad phase, narrow phase, solves and
// sleeping. At the end:
// the grains awake, the deepest overlaps, and the top centre just before the first collider's
// removal (a mould taken away).
#pragma once

#include <filesystem>
#include <limits>

#include "experiments/io/csv_table.hpp"
#include "experiments/scene/observer.hpp"

namespace rice::experiments {

class StatsObserver : public Observer {
 public:
  explicit StatsObserver(const std::filesystem::path& folder);
  void begin(const World& world) override;
  void observe(const World& world, const Stepper& stepper, int frame, double wall_seconds) override;
  void end(const World& world, const Stepper& stepper, SceneReport& report) override;
  /// The rows so far and the top before the removal.
  void save_state(xpbd::StateWriter& out) const override;
  void load_state(xpbd::StateReader& in) override;

 private:
  std::filesystem::path folder_;
  CsvTable stats_;
  double first_removal_ = INFINITY;  ///< the first collider's removal time [s]
  double top_before_removal_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace rice::experiments
