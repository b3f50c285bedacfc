// XPBD against the reference solver over substeps, iterations and resolution; see
// convergence_study.hpp.
#include "experiments/studies/convergence_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <tuple>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/item_loop.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "fem_reference/implicit_solver.hpp"
#include "fem_reference/trajectory_error.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {
namespace {

using Clock = std::chrono::steady_clock;
using xpbd::Positions;

/// One simulation setting shared by a reference trajectory and the XPBD runs against it.
struct Case {
  ConvergenceScene scene;
  BodyModel body;
  Damping damping;
  double rayleigh_time;  ///< τ of the damping; 0 when undamped
  int resolution;
  int substeps;
};

/// A state on the reference trajectory at the start of a frame, and the state one step later.
struct StepSample {
  Positions x, v, x_next;
};

struct Reference {
  Case setting;
  std::vector<Positions> frames;  ///< positions at frame ends; frames[0] is the start
  std::vector<StepSample> samples;
  double wall_per_sim_second = 0.0;
  double newton_iterations = 0.0;  ///< mean per step
  int unconverged_steps = 0;
  bool failed = false;
  int tets = 0;
};

int frame_count(const ConvergenceSettings& s) { return static_cast<int>(std::lround(s.duration / s.frame)); }

Reference run_reference(const ConvergenceSettings& s, const Case& c) {
  Reference ref{c, {}, {}};
  xpbd::Model model = make_scene(c.scene, c.body, s.bar, c.resolution, c.damping, c.rayleigh_time);
  ref.tets = static_cast<int>(std::max(model.neo_hookean.size(), model.volumes.size()));
  const double h = s.frame / c.substeps;
  fem::ImplicitSolver solver(model, {.time_step = h, .newton = {.tolerance = s.reference_tolerance}});
  ref.frames.push_back(model.particles.x);
  long newton_iterations = 0;
  const auto start = Clock::now();
  try {
    for (int f = 0; f < frame_count(s); ++f) {
      stop_point();
      for (int n = 0; n < c.substeps; ++n) {
        const bool sample = n == 0 && f % s.sample_every == 0;
        if (sample) ref.samples.push_back({model.particles.x, model.particles.v, {}});
        solver.step();
        if (sample) ref.samples.back().x_next = model.particles.x;
        newton_iterations += solver.report().iterations;
        if (!solver.report().converged) ++ref.unconverged_steps;
      }
      ref.frames.push_back(model.particles.x);
    }
  } catch (const xpbd::SimulationError&) {
    ref.failed = true;
  }
  ref.wall_per_sim_second = seconds_since(start) / s.duration;
  ref.newton_iterations = static_cast<double>(newton_iterations) / (frame_count(s) * c.substeps);
  return ref;
}

ConvergenceRun describe(const Case& c, const char* method, int tets) {
  ConvergenceRun run;
  run.scene = scene_name(c.scene);
  run.model = body_model_name(c.body);
  run.method = method;
  run.resolution = c.resolution;
  run.tets = tets;
  run.damping = damping_name(c.damping);
  run.rayleigh_time = c.rayleigh_time;
  run.substeps = c.substeps;
  return run;
}

/// The position-based variants the study compares, and vertex block descent.
enum class Variant { kXpbd, kXpbdPrimalCorrection, kPbd, kVbd };

const char* variant_name(Variant v) {
  switch (v) {
    case Variant::kXpbd: return "xpbd";
    case Variant::kXpbdPrimalCorrection: return "xpbd-primal";
    case Variant::kPbd: return "pbd";
    case Variant::kVbd: return "vbd";
  }
  return "";
}

xpbd::Method method_of(Variant v) {
  return v == Variant::kPbd ? xpbd::Method::kPbd : v == Variant::kVbd ? xpbd::Method::kVbd : xpbd::Method::kXpbd;
}

ConvergenceRun run_position_based(const ConvergenceSettings& s, const Reference& ref, int iterations,
                                  Variant variant) {
  const Case& c = ref.setting;
  ConvergenceRun run = describe(c, variant_name(variant), ref.tets);
  run.iterations = iterations;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  xpbd::Model model = make_scene(c.scene, c.body, s.bar, c.resolution, c.damping, c.rayleigh_time);
  xpbd::SolverSettings settings{.time_step = s.frame, .substeps = c.substeps, .iterations = iterations,
                                .method = method_of(variant),
                                .execution = xpbd::Execution::kSerial,
                                .primal_correction = variant == Variant::kXpbdPrimalCorrection};
  fem::TrajectoryError error;
  const auto start = Clock::now();
  try {
    xpbd::Solver solver(model, settings);
    for (int f = 0; f < frame_count(s); ++f) {
      stop_point();
      solver.step();
      error.add_frame(model.particles.x, ref.frames[f + 1]);
    }
  } catch (const xpbd::SimulationError&) {
    run.failed = true;
  }
  run.wall_per_sim_second = seconds_since(start) / s.duration;
  run.trajectory_error = run.failed ? kNaN : error.rms() / s.bar.length;
  run.max_frame_error = run.failed ? kNaN : error.max_frame_rms() / s.bar.length;

  // One step of h from reference states: XPBD's answer against Newton's.
  settings.time_step = s.frame / c.substeps;
  settings.substeps = 1;
  settings.diagnostics = true;
  double distance = 0.0, primal = 0.0, constraint = 0.0;
  try {
    for (const StepSample& sample : ref.samples) {
      model.particles.x = sample.x;
      model.particles.v = sample.v;
      xpbd::Solver one_step(model, settings);
      one_step.step();
      distance += fem::rms_distance(model.particles.x, sample.x_next);
      primal += one_step.diagnostics().primal_residual;
      constraint += one_step.diagnostics().constraint_residual;
    }
    const double count = static_cast<double>(ref.samples.size());
    run.step_distance = distance / count / s.bar.length;
    run.primal_residual = primal / count;
    run.constraint_residual = constraint / count;
  } catch (const xpbd::SimulationError&) {
    run.step_distance = run.primal_residual = run.constraint_residual = kNaN;
  }
  return run;
}

/// Marks the runs that no other run of the same method and panel beats in both error and cost.
void mark_pareto_fronts(std::vector<ConvergenceRun>& runs) {
  const auto panel = [](const ConvergenceRun& r) {
    return std::make_tuple(r.scene, r.model, r.method, r.damping, r.resolution);
  };
  for (ConvergenceRun& r : runs) {
    if (r.method == "reference" || r.failed) continue;
    r.pareto = std::none_of(runs.begin(), runs.end(), [&](const ConvergenceRun& o) {
      return &o != &r && !o.failed && panel(o) == panel(r) &&
             o.wall_per_sim_second <= r.wall_per_sim_second && o.trajectory_error <= r.trajectory_error &&
             (o.wall_per_sim_second < r.wall_per_sim_second || o.trajectory_error < r.trajectory_error);
    });
  }
}

std::vector<Case> reference_cases(const ConvergenceSettings& s) {
  std::vector<Case> cases;
  for (const ConvergenceScene scene : {ConvergenceScene::kHangingCantilever, ConvergenceScene::kTwistedBar}) {
    for (const Damping damping : {Damping::kNone, Damping::kConstraint})
      for (const int resolution : s.resolutions)
        for (const int n : resolution == s.grid_resolution ? s.substeps : s.resolution_substeps)
          cases.push_back({scene, BodyModel::kNeoHookean, damping, damping == Damping::kNone ? 0.0 : s.rayleigh_time,
                           resolution, n});
    for (const int n : s.substeps)  // strain-rate damping: vertex block descent only
      if (n <= s.max_vbd_substeps)
        cases.push_back({scene, BodyModel::kNeoHookean, Damping::kStrainRate, s.rayleigh_time, s.grid_resolution, n});
  }
  for (const int n : s.substeps)  // PBD's contrast: springs and volumes, undamped
    cases.push_back({ConvergenceScene::kHangingCantilever, BodyModel::kSprings, Damping::kNone, 0.0, s.grid_resolution, n});
  return cases;
}

void print_table(const ConvergenceSettings& s, const std::vector<ConvergenceRun>& runs,
                 const char* title, double ConvergenceRun::*figure) {
  std::printf("\n%s (resolution %d, relative to L = %g m)\n", title, s.grid_resolution, s.bar.length);
  std::map<std::tuple<std::string, std::string, std::string, std::string>, std::map<int, std::map<int, double>>>
      tables;
  for (const ConvergenceRun& r : runs)
    if (r.resolution == s.grid_resolution && r.method != "reference")
      tables[{r.scene, r.model, r.method, r.damping}][r.substeps][r.iterations] = r.*figure;
  for (const auto& [key, rows] : tables) {
    const auto& [scene, model, method, damping] = key;
    std::printf("%s, %s, %s, damping %s\n%8s", scene.c_str(), model.c_str(), method.c_str(), damping.c_str(),
                "N \\ K");
    for (int k : s.iterations) std::printf(" %10d", k);
    std::printf("\n");
    for (const auto& [n, row] : rows) {
      std::printf("%8d", n);
      for (int k : s.iterations) {
        const auto it = row.find(k);
        if (it == row.end()) std::printf(" %10s", "-");
        else std::printf(" %10.3e", it->second);
      }
      std::printf("\n");
    }
  }
}

}  // namespace

ConvergenceSettings ConvergenceSettings::quick() {
  ConvergenceSettings s;
  s.duration = 0.1;
  s.substeps = {1, 4, 16};
  s.iterations = {1, 5, 20};
  s.resolutions = {1, 2};
  s.resolution_substeps = {4};
  s.resolution_iterations = {5};
  s.sample_every = 2;
  return s;
}

void validate(const ConvergenceSettings& s) {
  if (!(s.duration >= s.frame) || s.substeps.empty() || s.iterations.empty() || s.sample_every < 1 ||
      std::find(s.resolutions.begin(), s.resolutions.end(), s.grid_resolution) == s.resolutions.end())
    throw std::invalid_argument("convergence study: need duration >= one frame, substeps and iterations, "
                                "sample_every >= 1, and grid_resolution among the resolutions");
  if (!(s.bar.young > 0.0) || !(s.rayleigh_time > 0.0))
    throw std::invalid_argument("convergence study: --young and --rayleigh-time must be positive");
}

std::vector<ConvergenceRun> run_convergence_study(const ConvergenceSettings& s) {
  validate(s);
  const std::vector<Case> cases = reference_cases(s);
  std::vector<Reference> references(cases.size());
  for_each_item("convergence: references", static_cast<int>(cases.size()),
                [&](int i) { references[i] = run_reference(s, cases[i]); });
  struct Job {
    size_t reference;
    int iterations;
    Variant variant;
  };
  std::vector<Job> jobs;
  for (size_t i = 0; i < cases.size(); ++i) {
    const bool grid = cases[i].resolution == s.grid_resolution;
    for (const int k : grid ? s.iterations : s.resolution_iterations) {
      if (cases[i].body == BodyModel::kSprings) {
        jobs.push_back({i, k, Variant::kPbd});
        continue;
      }
      if (grid && cases[i].substeps <= s.max_vbd_substeps) jobs.push_back({i, k, Variant::kVbd});
      if (cases[i].damping == Damping::kStrainRate) continue;  // XPBD refuses it
      jobs.push_back({i, k, Variant::kXpbd});
      if (grid) jobs.push_back({i, k, Variant::kXpbdPrimalCorrection});
    }
  }
  std::vector<ConvergenceRun> runs(jobs.size());
  for_each_item("convergence: position-based runs", static_cast<int>(jobs.size()), [&](int j) {
    runs[j] = run_position_based(s, references[jobs[j].reference], jobs[j].iterations, jobs[j].variant);
  });
  for (const Reference& ref : references) {
    ConvergenceRun run = describe(ref.setting, "reference", ref.tets);
    run.wall_per_sim_second = ref.wall_per_sim_second;
    run.failed = ref.failed || ref.unconverged_steps > 0;
    run.iterations = static_cast<int>(std::lround(ref.newton_iterations));
    runs.push_back(run);
  }
  mark_pareto_fronts(runs);
  return runs;
}

void convergence_study_command(const ConvergenceSettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  const auto start = Clock::now();
  const std::vector<ConvergenceRun> runs = run_convergence_study(s);
  CsvTable table({"scene", "model", "method", "resolution", "tets", "rayleigh_time_s", "substeps", "iterations",
                  "h_s", "wall_s_per_sim_s", "rms_error_rel", "max_frame_error_rel", "step_distance_rel",
                  "primal_residual", "constraint_residual", "pareto", "status", "damping"});
  for (const ConvergenceRun& r : runs)
    table.add_row({r.scene, r.model, r.method, cell(r.resolution), cell(r.tets), cell(r.rayleigh_time),
                   cell(r.substeps), cell(r.iterations), cell(s.frame / r.substeps), cell(r.wall_per_sim_second),
                   cell(r.trajectory_error), cell(r.max_frame_error), cell(r.step_distance),
                   cell(r.primal_residual), cell(r.constraint_residual), cell(r.pareto ? 1 : 0),
                   r.failed ? "failed" : "ok", r.damping});
  write_file_atomically(folder / "convergence.csv", table.text());

  print_table(s, runs, "Trajectory RMS error", &ConvergenceRun::trajectory_error);
  print_table(s, runs, "One-step distance to the Newton solution", &ConvergenceRun::step_distance);
  print_table(s, runs, "Primal residual |M(x - x~) - grad C^T lambda| [kg m]", &ConvergenceRun::primal_residual);
  std::printf("\nReference cost [s per simulated second] and mean Newton iterations per step:\n");
  for (const ConvergenceRun& r : runs)
    if (r.method == "reference")
      std::printf("  %-18s %-11s %-11s tau %-6g res %d N %3d: %9.3f s, %d it%s\n", r.scene.c_str(),
                  r.model.c_str(), r.damping.c_str(), r.rayleigh_time, r.resolution, r.substeps, r.wall_per_sim_second, r.iterations,
                  r.failed ? "  (FAILED or unconverged steps)" : "");

  const std::string grid = std::to_string(s.grid_resolution);
  render_plot(folder, "convergence", csv_plot_header("convergence", 2000, 1000) +
                                         "set multiplot layout 2,3 title 'XPBD is cheapest down to ~5e-3; with the "
                                         "primal correction, and vertex block descent (stable from 1 substep per "
                                         "frame, but dear), runs converge to the reference'\n" +
                                         kLogLogAxes + R"(set xlabel 'wall time per simulated second [s]'
set ylabel 'RMS vertex error / length'
set cblabel 'log2 substeps per frame'
set key bottom left
G = )" + grid + R"(
sel(scene, method, damping) = strcol(1) eq scene && strcol(3) eq method && $4 == G && strcol(18) eq damping
do for [scene in 'hanging-cantilever twisted-bar'] {
  do for [damping in 'none constraint strain-rate'] {
    set title sprintf('%s, damping: %s', scene, damping)
    plot 'convergence.csv' using (sel(scene, 'xpbd', damping) ? $10 : 1/0):11:(log($7)/log(2)) with points pt 7 ps 1.2 palette title 'XPBD (N, K grid)', \
         '' using (sel(scene, 'xpbd', damping) && $16 == 1 ? $10 : 1/0):11 with points pt 4 ps 2.2 lw 2 lc rgb 'black' title 'XPBD Pareto front', \
         '' using (sel(scene, 'xpbd-primal', damping) ? $10 : 1/0):11 with points pt 9 ps 1.4 lc rgb 'dark-green' title 'XPBD + primal correction', \
         '' using (sel(scene, 'vbd', damping) ? $10 : 1/0):11:(log($7)/log(2)) with points pt 5 ps 1.2 palette title 'vertex block descent (squares)', \
         '' using (sel(scene, 'vbd', damping) && $16 == 1 ? $10 : 1/0):11 with points pt 6 ps 2.4 lw 2 lc rgb 'blue' title 'VBD Pareto front', \
         '' using (sel(scene, 'pbd', damping) ? $10 : 1/0):11 with points pt 6 ps 1.2 lc rgb 'red' title 'PBD (springs, vs its reference)'
  }
}
unset multiplot
)");
  stop_point();  // a Ctrl-C while gnuplot ran (it does not get the signal) stops here
  render_plot(folder, "convergence_resolution", csv_plot_header("convergence_resolution", 1400, 500) +
                                                    "set multiplot layout 1,2\n" + kLogLogAxes + R"(set xlabel 'wall time per simulated second [s]'
set ylabel 'RMS vertex error / length (vs reference at that resolution)'
set key bottom left
do for [scene in 'hanging-cantilever twisted-bar'] {
  set title sprintf('%s: resolution axis (XPBD, no damping)', scene)
  plot for [r in ')" + [&] {
    std::string list;
    for (int r : s.resolutions) {
      if (!list.empty()) list += ' ';
      list += std::to_string(r);
    }
    return list;
  }() + R"('] 'convergence.csv' using (strcol(1) eq scene && strcol(3) eq 'xpbd' && $4 == r+0 && strcol(18) eq 'none' ? $10 : 1/0):11 with points pt 7 ps 1.2 title sprintf('%s cells across', r)
}
unset multiplot
)");
  stop_point();  // a Ctrl-C while gnuplot ran (it does not get the signal) stops here
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"study", "convergence"},
                                  {"duration_s", cell(s.duration)},
                                  {"young_pa", cell(s.bar.young)},
                                  {"rayleigh_time_s", cell(s.rayleigh_time)},
                                  {"reference_tolerance", cell(s.reference_tolerance)},
                                  {"runs", cell(static_cast<long>(runs.size()))},
                                  {"wall_s", cell(seconds_since(start))}}));
  std::printf("\nwall time %.1f s\n", seconds_since(start));
}

}  // namespace rice::experiments
