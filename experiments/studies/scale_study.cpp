// `rice study scale`; see scale_study.hpp.
#include "experiments/studies/scale_study.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/studies/scene_child_run.hpp"

namespace rice::experiments {
namespace {

/// What one run measured.
struct ScaleRun {
  double simulation_s = 0.0, broad_s = 0.0, narrow_s = 0.0, solve_s = 0.0, sleeping_s = 0.0;
  double peak_mib = 0.0, contacts = 0.0, awake = 0.0;
};

ScaleRun measure_run(const ScaleStudySettings& s, const std::string& body, int count,
                     const std::filesystem::path& out) {
  const SceneChildRun run{s.scene,
                          {"grains.count=" + std::to_string(count), "grains.body=\"" + body + "\"",
                           "solver.frames=" + std::to_string(s.frames), "emitter.radius_m=" + cell(clump_radius(count))},
                          s.threads};
  run_scene_child(run, out, "scale: the run of " + std::to_string(count) + " " + body + " grains");
  const NumericCsv stats = read_numeric_csv(out / "stats.csv");
  double contacts = 0.0;  // the mean over the frames: the last alone is one moment of a settling pile
  for (const std::vector<double>& row : stats.rows) contacts += row[stats.column("contacts")] / stats.rows.size();
  return {info_number(out, "simulation_wall_s"), info_number(out, "broad_phase_s"), info_number(out, "narrow_phase_s"),
          info_number(out, "solve_s"), info_number(out, "sleeping_s"), info_number(out, "peak_memory_mib"),
          contacts, stats.rows.back()[stats.column("awake")]};
}

/// Time per grain-frame and its solves' part against grains, a line of each for every body run
/// (a body not run has no line in the key).
void plot_scale(const std::filesystem::path& folder, const std::vector<std::string>& bodies) {
  std::string plot = "plot 'scale.csv'";
  for (size_t k = 0; k < bodies.size(); ++k) {
    const std::string rows = "(strcol(1) eq '" + bodies[k] + "' ? $2 : 1/0)";
    const std::string point = bodies[k] == "rigid" ? "7" : "5", open_point = bodies[k] == "rigid" ? "6" : "4";
    plot += std::string(k == 0 ? " " : ", \\\n     '' ") + "using " + rows + ":4 with linespoints pt " + point +
            " title '" + bodies[k] + "', \\\n     '' using " + rows + ":7 with linespoints dt 2 pt " + open_point +
            " title '" + bodies[k] + ", solves'";
  }
  render_plot(folder, "scale", csv_plot_header("scale", 800, 500) + kLogLogAxes + R"(
set xlabel 'grains'
set ylabel 'wall time per grain-frame [µs]'
set key top left
)" + plot + "\n");
}

}  // namespace

ScaleStudySettings ScaleStudySettings::quick() {
  ScaleStudySettings s;
  s.counts = {20, 60};
  s.frames = 10;
  return s;
}

void validate(const ScaleStudySettings& s) {
  if (!std::filesystem::is_regular_file(s.scene)) throw std::invalid_argument("--scene: no file " + s.scene.string());
  if (s.counts.empty() || s.frames < 1 || s.threads < 0)
    throw std::invalid_argument("--counts and --frames must be given");
  for (size_t k = 0; k < s.counts.size(); ++k)
    if (s.counts[k] < 1 || s.counts[k] > 100000 || (k > 0 && s.counts[k] <= s.counts[k - 1]))
      throw std::invalid_argument("--counts must rise, each in [1, 100000]");
  for (const std::string& body : s.bodies)
    if (body != "rigid" && body != "soft") throw std::invalid_argument("--bodies: rigid or soft, not " + body);
}

double clump_radius(int count) { return 0.02 * std::cbrt(count / 100.0); }

void scale_study_command(const ScaleStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  CsvTable table({"body", "grains", "simulation_s", "us_per_grain_frame", "broad_phase_us", "narrow_phase_us",
                  "solve_us", "sleeping_us", "peak_memory_mib", "kib_per_grain_over_smallest", "contacts_per_grain",
                  "awake_at_end"});
  for (const std::string& body : s.bodies) {
    double smallest_mib = 0.0;
    for (size_t k = 0; k < s.counts.size(); ++k) {
      const int n = s.counts[k];
      const ScaleRun r = measure_run(s, body, n, folder / (body + "_" + std::to_string(n)));
      const double grain_frames = static_cast<double>(n) * s.frames, us = 1e6 / grain_frames;
      if (k == 0) smallest_mib = r.peak_mib;
      const std::string per_grain = k == 0 ? "nan" : cell(1024.0 * (r.peak_mib - smallest_mib) / (n - s.counts[0]));
      table.add_row({body, cell(n), cell(r.simulation_s), cell(us * r.simulation_s), cell(us * r.broad_s),
                     cell(us * r.narrow_s), cell(us * r.solve_s), cell(us * r.sleeping_s), cell(r.peak_mib), per_grain,
                     cell(r.contacts / n), cell(r.awake)});
      std::printf("scale: %d %s grains, %d frames: %.1f s, %.1f us per grain-frame, peak %.0f MiB, %.2f contacts "
                  "per grain\n", n, body.c_str(), s.frames, r.simulation_s, us * r.simulation_s, r.peak_mib,
                  r.contacts / n);
      std::fflush(stdout);  // a line per run, as it ends
      write_file_atomically(folder / "scale.csv", table.text());  // what is done so far, re-plottable
    }
  }
  plot_scale(folder, s.bodies);
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "study scale"},
                                  {"scene", s.scene.string()},
                                  {"frames", cell(s.frames)},
                                  {"threads", s.threads > 0 ? cell(s.threads) : "the machine's"}}));
}

}  // namespace rice::experiments
