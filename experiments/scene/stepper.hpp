// The stepper of a scene run: the xpbd solver at the scene's frame rate, with its substeps
// and iterations, by XPBD or vertex block descent ([solver]). Sleeping ([effects] sleeping)
// and the removal of colliders at their times happen inside its steps.
#pragma once

#include "experiments/scene/emitter.hpp"
#include "experiments/scene/scene.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {

/// The solver settings a scene asks for: a step of one frame, its substeps and iterations.
xpbd::SolverSettings solver_settings(const Scene& scene);

class Stepper {
 public:
  /// Throws std::invalid_argument for settings the model cannot run.
  Stepper(xpbd::Model& model, const Scene& scene) : solver_(model, solver_settings(scene)) {}

  /// Advances the world by one frame.
  void step() { solver_.step(); }

  /// Simulated time at the start of the next frame [s].
  double time() const { return solver_.time(); }
  const xpbd::ContactStatistics& contacts() const { return solver_.contacts()->statistics(); }
  /// For each body, how many others it is bonded to.
  std::vector<int> bonded_neighbours() const { return solver_.contacts()->bonded_neighbours(); }
  const xpbd::SolverTimings& timings() const { return solver_.timings(); }

  /// Its settings and where its time went, for run_info.txt.
  void report(RunInfoEntries& info) const;

  /// The model's and the solver's state between frames, for checkpoints.
  void save_state(xpbd::StateWriter& out) const { solver_.save_state(out); }
  void load_state(xpbd::StateReader& in) { solver_.load_state(in); }

 private:
  xpbd::Solver solver_;
};

}  // namespace rice::experiments
