// The scene-scale convergence study; see scene_convergence_study.hpp.
#include "experiments/studies/scene_convergence_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_run.hpp"

namespace rice::experiments {
namespace {

struct RunSetting {
  std::string method;  ///< "xpbd" or "vbd"
  int substeps = 0, iterations = 0;
  bool reference = false;
  std::string name() const { return method + "_" + std::to_string(substeps) + "x" + std::to_string(iterations); }
};

struct GridRun {
  RunSetting setting;
  SceneResult result;
  std::vector<xpbd::Vec3> centres;
  double centre_error = 0.0, top_error = 0.0;  ///< against the reference: RMS / L, and [m]
  bool pareto = false;
};

/// The grid, XPBD then vertex block descent, and the reference last.
std::vector<RunSetting> grid(const SceneConvergenceSettings& s) {
  std::vector<RunSetting> runs;
  for (const int n : s.xpbd_substeps)
    for (const int k : s.xpbd_iterations) runs.push_back({"xpbd", n, k});
  for (const int n : s.vbd_substeps)
    for (const int k : s.vbd_sweeps) runs.push_back({"vbd", n, k});
  runs.push_back({"xpbd", s.reference_substeps, s.reference_iterations, true});
  return runs;
}

std::vector<xpbd::Vec3> final_centres(const std::filesystem::path& run) {
  const NumericCsv csv = read_numeric_csv(run / "final_centres.csv");
  std::vector<xpbd::Vec3> centres;
  for (const auto& row : csv.rows)
    centres.emplace_back(row[csv.column("x")], row[csv.column("y")], row[csv.column("z")]);
  return centres;
}

/// One run of the scene, soft grains, without its render.
GridRun run_one(const SceneConvergenceSettings& s, const RunSetting& setting, const std::filesystem::path& folder) {
  Scene scene = read_scene_file(
      s.scene, {"grains.body=\"soft\"", "grains.count=" + std::to_string(s.count), "solver.frames=" + std::to_string(s.frames),
                "solver.method=\"" + setting.method + "\"", "solver.substeps=" + std::to_string(setting.substeps),
                "solver.iterations=" + std::to_string(setting.iterations)});
  scene.render.reset();
  // Both methods solve the same problem, the paper's damping, so that they approach one answer.
  scene.solver.vbd_strain_rate_damping = false;
  GridRun run{setting, run_scene(scene, folder / setting.name()), {}};
  run.centres = final_centres(folder / setting.name());
  return run;
}

/// Each run's errors against the reference (the last run), over the grains both placed.
void compare(std::vector<GridRun>& runs) {
  const GridRun& reference = runs.back();
  for (GridRun& run : runs) {
    const size_t n = std::min(run.centres.size(), reference.centres.size());
    double sum = 0.0;
    for (size_t g = 0; g < n; ++g) sum += (run.centres[g] - reference.centres[g]).squaredNorm();
    run.centre_error = n > 0 ? std::sqrt(sum / n) / reference.result.grain_length : NAN;
    run.top_error = std::abs(run.result.top - reference.result.top);
  }
}

/// Marks the runs no other run beats in both wall time and top error (the reference aside).
void mark_pareto_front(std::vector<GridRun>& runs) {
  for (GridRun& a : runs) {
    if (a.setting.reference) continue;
    a.pareto = std::none_of(runs.begin(), runs.end(), [&](const GridRun& b) {
      return !b.setting.reference && &b != &a && b.result.simulation_seconds <= a.result.simulation_seconds &&
             b.top_error <= a.top_error &&
             (b.result.simulation_seconds < a.result.simulation_seconds || b.top_error < a.top_error);
    });
  }
}

CsvTable table_of(const std::vector<GridRun>& runs) {
  CsvTable table({"run", "method", "substeps", "iterations", "reference", "wall_s", "centre_rms_over_length",
                  "top_m", "top_error_m", "packing_fraction", "deepest_overlap_m", "kinetic_energy_j", "awake",
                  "pareto"});
  for (const GridRun& r : runs)
    table.add_row({r.setting.name(), r.setting.method, cell(r.setting.substeps), cell(r.setting.iterations),
                   r.setting.reference ? "1" : "0", cell(r.result.simulation_seconds), cell(r.centre_error),
                   cell(r.result.top), cell(r.top_error), cell(r.result.packing_fraction),
                   cell(r.result.penetration.deepest()), cell(r.result.kinetic_energy), cell(r.result.awake),
                   r.pareto ? "1" : "0"});
  return table;
}

void plot(const std::filesystem::path& folder, const std::vector<GridRun>& runs) {
  CsvTable front({"wall_s", "top_error_m"});
  std::vector<const GridRun*> on_front;
  for (const GridRun& r : runs)
    if (r.pareto) on_front.push_back(&r);
  std::sort(on_front.begin(), on_front.end(),
            [](const GridRun* a, const GridRun* b) { return a->result.simulation_seconds < b->result.simulation_seconds; });
  std::string title = "Pareto front:";
  for (const GridRun* r : on_front) {
    front.add_row({cell(r->result.simulation_seconds), cell(r->top_error)});
    title += " " + r->setting.name();
  }
  write_file_atomically(folder / "scene_convergence_front.csv", front.text());
  render_plot(folder, "scene_convergence", csv_plot_header("scene_convergence", 900, 600) + R"(set logscale xy
set xlabel 'wall time of the simulation [s]'
set ylabel 'top centre: distance from the reference [m]'
set title ')" + title + R"(' noenhanced
set key right top
plot 'scene_convergence.csv' using 6:(strcol(2) eq 'xpbd' && $5 == 0 ? $9 : 1/0) with points pt 7 ps 1.5 title 'XPBD', \
     '' using 6:(strcol(2) eq 'vbd' ? $9 : 1/0) with points pt 5 ps 1.5 title 'vertex block descent', \
     '' using 6:($5 == 0 ? $9 : 1/0):1 with labels offset 0,1 font ',8' noenhanced notitle, \
     'scene_convergence_front.csv' using 1:2 with lines lw 2 dt 2 title 'Pareto front'
)");
}

}  // namespace

SceneConvergenceSettings SceneConvergenceSettings::quick() {
  SceneConvergenceSettings s;
  s.count = 12;
  s.frames = 8;
  s.xpbd_substeps = {120, 240};
  s.xpbd_iterations = {1};
  s.vbd_substeps = {5, 10};
  s.vbd_sweeps = {5};
  s.reference_substeps = 480;
  s.reference_iterations = 1;
  return s;
}

void validate(const SceneConvergenceSettings& s) {
  const auto in = [](const std::vector<int>& v, const char* name) {
    if (v.empty()) throw std::invalid_argument(std::string("scene-convergence: give at least one ") + name);
    for (const int n : v)
      if (n < 1 || n > 10000) throw std::invalid_argument(std::string("scene-convergence: ") + name + " in [1, 10000]");
  };
  in(s.xpbd_substeps, "--xpbd-substeps");
  in(s.xpbd_iterations, "--xpbd-iterations");
  in(s.vbd_substeps, "--vbd-substeps");
  in(s.vbd_sweeps, "--vbd-sweeps");
  in({s.reference_substeps}, "--reference-substeps");
  in({s.reference_iterations}, "--reference-iterations");
  if (s.count < 1 || s.frames < 1) throw std::invalid_argument("scene-convergence: --count and --frames must be positive");
  if (!std::filesystem::exists(s.scene)) throw std::invalid_argument("scene-convergence: no scene " + s.scene.string());
}

void scene_convergence_study_command(const SceneConvergenceSettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<RunSetting> settings = grid(s);
  std::vector<GridRun> runs;
  for (size_t k = 0; k < settings.size(); ++k) {
    std::printf("scene-convergence: run %zu/%zu, %s\n", k + 1, settings.size(), settings[k].name().c_str());
    runs.push_back(run_one(s, settings[k], folder));
    stop_point();
  }
  compare(runs);
  mark_pareto_front(runs);
  write_file_atomically(folder / "scene_convergence.csv", table_of(runs).text());
  plot(folder, runs);
  write_file_atomically(folder / "run_info.txt", run_info({{"study", "scene-convergence"},
                                                           {"scene", s.scene.string()},
                                                           {"count", cell(s.count)},
                                                           {"frames", cell(s.frames)},
                                                           {"runs", cell(static_cast<long>(runs.size()))},
                                                           {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
