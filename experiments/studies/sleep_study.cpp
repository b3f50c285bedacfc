// `rice study sleep`; see sleep_study.hpp.
#include "experiments/studies/sleep_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/studies/scene_child_run.hpp"

namespace rice::experiments {
namespace {

/// One run's settled pile and cost.
struct SleepRun {
  std::vector<double> heights, radii;  ///< the grains' centres: z, and distance from the axis [m]
  double simulation_s = 0.0, awake = 0.0, top = 0.0, kinetic_energy = 0.0, penetration = 0.0;
};

/// The scene with the study's count and frames and the run's own `overrides` (as --set takes them).
SleepRun run_pile(const SleepStudySettings& s, std::vector<std::string> overrides, const std::filesystem::path& out) {
  overrides.push_back("grains.count=" + std::to_string(s.count));
  overrides.push_back("solver.frames=" + std::to_string(s.frames));
  run_scene_child({s.scene, overrides, s.threads}, out, "sleep: the run into " + out.string());
  const NumericCsv centres = read_numeric_csv(out / "final_centres.csv");
  const NumericCsv stats = read_numeric_csv(out / "stats.csv");
  SleepRun r;
  for (const std::vector<double>& row : centres.rows) {
    r.heights.push_back(row[centres.column("z")]);
    r.radii.push_back(row[centres.column("r")]);
  }
  const std::vector<double>& last = stats.rows.back();
  r.simulation_s = info_number(out, "simulation_wall_s");
  r.awake = last[stats.column("awake")];
  r.top = last[stats.column("top_m")];
  r.kinetic_energy = last[stats.column("kinetic_energy_j")];
  r.penetration = last[stats.column("max_penetration_m")];
  return r;
}

void plot_sleep(const std::filesystem::path& folder) {
  render_plot(folder, "sleep", csv_plot_header("sleep", 800, 560) + R"(
set xlabel 'wall time of the run [s]'
set ylabel 'settled pile off the run without sleeping [µm]'
set key below
set offsets graph 0.05, graph 0.1, graph 0.05, 0
plot 'sleep.csv' using (strcol(1) eq 'frames' ? $5 : 1/0):($11 * 1e6):3 with labels offset 1,1 notitle, \
     '' using (strcol(1) eq 'speed' ? $5 : 1/0):($11 * 1e6):(sprintf('%g m/s', $2)) with labels offset 1,2 notitle, \
     '' using (strcol(1) eq 'frames' ? $5 : 1/0):($11 * 1e6) with linespoints pt 7 title 'heights, by frames at rest', \
     '' using (strcol(1) eq 'speed' ? $5 : 1/0):($11 * 1e6) with linespoints pt 5 title 'heights, by speed', \
     '' using (strcol(1) eq 'frames' ? $5 : 1/0):($12 * 1e6) with linespoints dt 2 pt 6 \
        title 'distances from the axis, by frames', \
     '' using (strcol(1) eq 'off' ? $5 : 1/0):(0) with points pt 9 ps 2 title 'sleeping off (the reference)', \
     '' using (strcol(1) eq 'twin' ? $5 : 1/0):($11 * 1e6) with points pt 11 ps 2 \
        title 'its twin, 1 substep more: the noise floor'
)");
}

}  // namespace

SleepStudySettings SleepStudySettings::quick() {
  SleepStudySettings s;
  s.count = 40;
  s.frames = 30;
  s.sleep_frames = {5, 15};
  s.sleep_speeds = {2e-3};
  return s;
}

void validate(const SleepStudySettings& s) {
  if (!std::filesystem::is_regular_file(s.scene)) throw std::invalid_argument("--scene: no file " + s.scene.string());
  if (s.count < 1 || s.count > 100000 || s.frames < 1 || s.threads < 0)
    throw std::invalid_argument("--count in [1, 100000] and --frames >= 1");
  if (s.sleep_frames.empty() && s.sleep_speeds.empty())
    throw std::invalid_argument("--sleep-frames or --sleep-speeds must name a setting");
  for (int f : s.sleep_frames)
    if (f < 1) throw std::invalid_argument("--sleep-frames: each >= 1");
  for (double v : s.sleep_speeds)
    if (!(v > 0.0 && v < 1.0)) throw std::invalid_argument("--sleep-speeds: each in (0, 1) m/s");
}

double wasserstein_1(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) throw std::invalid_argument("wasserstein_1: an empty sample");
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  const size_t m = std::max(a.size(), b.size());
  const auto quantile = [m](const std::vector<double>& v, size_t i) { return v[i * v.size() / m]; };
  double sum = 0.0;
  for (size_t i = 0; i < m; ++i) sum += std::abs(quantile(a, i) - quantile(b, i));
  return sum / m;
}

void sleep_study_command(const SleepStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  CsvTable table({"knob", "speed_m_s", "frames_at_rest", "grains", "simulation_s", "time_over_reference",
                  "awake_at_end", "top_m", "kinetic_energy_j", "max_penetration_m", "height_w1_m", "axis_w1_m"});
  const SleepRun reference = run_pile(s, {"effects.sleeping=false"}, folder / "off");
  const auto add = [&](const std::string& knob, double speed, int frames, const SleepRun& r) {
    const double height_error = wasserstein_1(r.heights, reference.heights);
    const double axis_error = wasserstein_1(r.radii, reference.radii);
    const bool sleeps = knob == "frames" || knob == "speed";
    table.add_row({knob, sleeps ? cell(speed) : "nan", sleeps ? cell(frames) : "nan",
                   cell(static_cast<long>(r.heights.size())), cell(r.simulation_s),
                   cell(r.simulation_s / reference.simulation_s), cell(r.awake), cell(r.top), cell(r.kinetic_energy),
                   cell(r.penetration), cell(height_error), cell(axis_error)});
    std::printf("sleep: %s, %g m/s, %d frames: %.1f s (%.2f of sleeping off), %g awake, heights %.1f um off\n",
                knob.c_str(), speed, frames, r.simulation_s, r.simulation_s / reference.simulation_s, r.awake,
                1e6 * height_error);
    std::fflush(stdout);
    write_file_atomically(folder / "sleep.csv", table.text());  // what is done so far, re-plottable
  };
  add("off", 0.0, 0, reference);
  // The noise floor: the reference again with one substep more a frame, a perturbation of
  // 1/N in the step. A pile is chaotic, so its twin settles this far off without any sleep.
  const int substeps = static_cast<int>(info_number(folder / "off", "substeps"));
  add("twin", 0.0, 0,
      run_pile(s, {"effects.sleeping=false", "solver.substeps=" + std::to_string(substeps + 1)}, folder / "twin"));
  const SceneEffects defaults = read_scene_file(s.scene).effects;  // the scene's own sleep rule
  std::optional<SleepRun> at_defaults;  // run once, in whichever sweep meets it first
  for (int frames : s.sleep_frames) {
    const SleepRun r = run_pile(s, {"effects.sleep_frames=" + std::to_string(frames)},
                                folder / ("frames_" + std::to_string(frames)));
    if (frames == defaults.sleep_frames) at_defaults = r;
    add("frames", defaults.sleep_speed, frames, r);
  }
  for (double speed : s.sleep_speeds) {
    const bool known = speed == defaults.sleep_speed && at_defaults;
    add("speed", speed, defaults.sleep_frames,
        known ? *at_defaults
              : run_pile(s, {"effects.sleep_speed_m_s=" + cell(speed)}, folder / ("speed_" + cell(speed))));
  }
  plot_sleep(folder);
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "study sleep"},
                                  {"scene", s.scene.string()},
                                  {"grains", cell(s.count)},
                                  {"frames", cell(s.frames)},
                                  {"threads", s.threads > 0 ? cell(s.threads) : "the machine's"}}));
}

}  // namespace rice::experiments
