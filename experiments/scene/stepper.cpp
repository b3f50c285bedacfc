// The stepper of a scene run; see stepper.hpp.
#include "experiments/scene/stepper.hpp"

#include "experiments/io/csv_table.hpp"

namespace rice::experiments {

xpbd::SolverSettings solver_settings(const Scene& scene) {
  xpbd::SolverSettings settings;
  settings.time_step = 1.0 / scene.solver.fps;
  settings.substeps = substeps_per_frame(scene);
  settings.iterations = scene.solver.iterations;
  if (scene.solver.vertex_block_descent) settings.method = xpbd::Method::kVbd;
  return settings;
}

void Stepper::report(RunInfoEntries& info) const {
  const xpbd::SolverSettings& s = solver_.settings();
  const xpbd::SolverTimings& t = timings();
  info.push_back({"substeps", cell(s.substeps)});
  info.push_back({"iterations", cell(s.iterations)});
  info.push_back({"method", s.method == xpbd::Method::kVbd ? "vbd" : "xpbd"});
  info.push_back({"broad_phase_s", cell(t.broad_phase)});
  info.push_back({"narrow_phase_s", cell(t.narrow_phase)});
  info.push_back({"solve_s", cell(t.solve())});
  info.push_back({"sleeping_s", cell(t.sleeping)});
}

}  // namespace rice::experiments
