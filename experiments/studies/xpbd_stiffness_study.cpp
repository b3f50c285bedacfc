// The XPBD-versus-PBD stiffness study; see xpbd_stiffness_study.hpp.
#include "experiments/studies/xpbd_stiffness_study.hpp"

#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/item_loop.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {
namespace {

using namespace rice::xpbd;

const std::vector<std::string> kMethods = {"xpbd-neo-hookean", "xpbd-springs", "pbd-springs"};

struct Cantilever {
  Model model;
  int tip;  ///< vertex on the free end's centre line
};

Cantilever make_cantilever(const StiffnessStudySettings& s, const std::string& method) {
  const TetMesh mesh = make_box_tet_mesh(Vec3(s.length, s.width, s.width), s.cells_along, 2, 2);
  Cantilever c;
  c.model.particles = make_particles(mesh, s.density);
  if (method == "xpbd-neo-hookean") {
    add_neo_hookean_tets(c.model, mesh, lame_from_young_poisson(s.young, s.poisson));
  } else {
    add_edge_springs(c.model, mesh, s.young);
    add_tet_volumes(c.model, mesh, s.young / (3.0 * (1.0 - 2.0 * s.poisson)));
  }
  pin_particles(c.model, vertices_at_min_x(mesh.V));
  c.tip = box_vertex_index(s.cells_along, 2, s.cells_along, 1, 1);
  return c;
}

StiffnessRun run_one(const StiffnessStudySettings& s, const std::string& method, int iterations) {
  const auto start = std::chrono::steady_clock::now();
  Cantilever c = make_cantilever(s, method);
  const double rest_height = c.model.particles.x(c.tip, 2);
  // Serial: a 240-tet mesh has too few constraints per colour to gain from threads.
  SolverSettings solver_settings{.time_step = s.time_step, .substeps = s.substeps, .iterations = iterations,
                                 .execution = Execution::kSerial};
  solver_settings.method = method.rfind("pbd", 0) == 0 ? Method::kPbd : Method::kXpbd;
  solver_settings.pbd_stiffness = s.pbd_stiffness;
  Solver solver(c.model, solver_settings);
  StiffnessRun run{method, iterations, 0.0, 0, false, 0.0};
  int frames_at_rest = 0;
  while (run.frames < s.max_frames && !run.reached_rest) {
    stop_point();
    solver.step();
    ++run.frames;
    frames_at_rest = max_speed(c.model.particles) < s.rest_speed ? frames_at_rest + 1 : 0;
    run.reached_rest = frames_at_rest >= s.rest_frames;
    c.model.particles.v *= s.settle_velocity_scale;
  }
  run.tip_deflection = rest_height - c.model.particles.x(c.tip, 2);
  run.wall_seconds = seconds_since(start);
  return run;
}

}  // namespace

std::vector<StiffnessRun> run_stiffness_study(const StiffnessStudySettings& settings) {
  // The runs are independent: they run side by side, one per core, each solver serial.
  const int per_method = static_cast<int>(settings.iterations.size());
  const int count = static_cast<int>(kMethods.size()) * per_method;
  std::vector<StiffnessRun> runs(count);
  for_each_item("xpbd-stiffness", count, [&](int r) {
    runs[r] = run_one(settings, kMethods[r / per_method], settings.iterations[r % per_method]);
  });
  return runs;
}

double relative_spread(const std::vector<StiffnessRun>& runs, const std::string& method) {
  std::vector<double> d;
  for (const StiffnessRun& r : runs)
    if (r.method == method) d.push_back(r.tip_deflection);
  if (d.empty()) return 0.0;
  const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
  double mean = 0.0;
  for (const double x : d) mean += x / d.size();
  return (*hi - *lo) / mean;
}

void validate(const StiffnessStudySettings& s) {
  if (s.iterations.empty() || *std::min_element(s.iterations.begin(), s.iterations.end()) < 1)
    throw std::invalid_argument("xpbd-stiffness: --iterations needs counts >= 1");
  if (s.substeps < 1) throw std::invalid_argument("xpbd-stiffness: --substeps must be >= 1");
  if (!(s.young > 0.0)) throw std::invalid_argument("xpbd-stiffness: --young must be positive");
  if (!(s.pbd_stiffness > 0.0 && s.pbd_stiffness <= 1.0))
    throw std::invalid_argument("xpbd-stiffness: --pbd-stiffness must be in (0, 1]");
}

void stiffness_study_command(const StiffnessStudySettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  make_output_folder(folder);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<StiffnessRun> runs = run_stiffness_study(settings);

  CsvTable table({"method", "iterations", "substeps", "substep_s", "tip_deflection_m", "frames",
                  "reached_rest", "wall_s"});
  std::printf("%-18s %10s %18s %8s %8s\n", "method", "iterations", "tip deflection [m]", "frames", "wall [s]");
  for (const StiffnessRun& r : runs) {
    table.add_row({r.method, cell(r.iterations), cell(settings.substeps),
                   cell(settings.time_step / settings.substeps), cell(r.tip_deflection),
                   cell(r.frames), r.reached_rest ? "1" : "0", cell(r.wall_seconds)});
    std::printf("%-18s %10d %18.6e %8d %8.2f%s\n", r.method.c_str(), r.iterations, r.tip_deflection,
                r.frames, r.wall_seconds, r.reached_rest ? "" : "  (not at rest)");
  }
  write_file_atomically(folder / "stiffness.csv", table.text());

  render_plot(folder, "stiffness", R"(set terminal pngcairo size 900,600
set output 'stiffness.png'
set datafile separator ','
set logscale xy
set format y '10^{%L}'
set xlabel 'iterations per substep K'
set ylabel 'rest tip deflection [mm] (log)'
set title 'Cantilever under gravity: XPBD stiffness does not depend on K, PBD stiffness does'
set key left top
plot for [m in "xpbd-neo-hookean xpbd-springs pbd-springs"] 'stiffness.csv' \
     using 2:(strcol(1) eq m ? 1000*$5 : 1/0) with linespoints title m
)");
  stop_point();  // a Ctrl-C while gnuplot ran (it does not get the signal) stops here
  const double total = seconds_since(start);
  write_file_atomically(
      folder / "run_info.txt",
      run_info({{"study", "xpbd-stiffness"},
                {"cantilever", cell(settings.length) + " m x " + cell(settings.width) + " m x " +
                                   cell(settings.width) + " m, " + cell(settings.cells_along) + "x2x2 cubes"},
                {"young_pa", cell(settings.young)},
                {"poisson", cell(settings.poisson)},
                {"density", cell(settings.density)},
                {"substep_s", cell(settings.time_step / settings.substeps)},
                {"pbd_stiffness", cell(settings.pbd_stiffness)},
                {"threads", cell(static_cast<long>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)))},
                {"wall_s", cell(total)}}));
  std::printf("relative spread of the rest tip deflection over K = %d..%d:\n",
              settings.iterations.front(), settings.iterations.back());
  for (const std::string& method : kMethods)
    std::printf("  %-18s %.3e\n", method.c_str(), relative_spread(runs, method));
  std::printf("spread: xpbd %.3e, pbd %.3e (total %.1f s)\n", relative_spread(runs, "xpbd-neo-hookean"),
              relative_spread(runs, "pbd-springs"), total);
}

}  // namespace rice::experiments
