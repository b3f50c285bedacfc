// The pour's substep study; see pour_substep_study.hpp.
#include "experiments/studies/pour_substep_study.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/scene/scene_run.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"

namespace rice::experiments {

void validate(const PourSubstepStudySettings& settings) {
  if (settings.substeps.empty()) throw std::invalid_argument("pour-substeps: give at least one --substeps count");
  for (const int n : settings.substeps)
    if (n < 1 || n > 10000) throw std::invalid_argument("pour-substeps: --substeps counts must be in [1, 10000]");
  validate(settings.scene);
}

void pour_substep_study_command(const PourSubstepStudySettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  make_output_folder(folder);
  const auto start = std::chrono::steady_clock::now();
  CsvTable table({"substeps", "substep_s", "wall_s", "penetration_between_grains_m", "penetration_into_container_m",
                  "awake_at_end"});
  std::vector<SceneResult> results;
  for (size_t k = 0; k < settings.substeps.size(); ++k) {
    const int n = settings.substeps[k];
    std::printf("pour-substeps: run %zu/%zu, %d substeps per frame\n", k + 1, settings.substeps.size(), n);
    Scene scene = settings.scene;
    scene.solver.substeps = n;
    const SceneResult r = run_scene(scene, folder / ("substeps_" + std::to_string(n)));
    results.push_back(r);
    table.add_row({cell(n), cell(1.0 / (scene.solver.fps * n)), cell(r.simulation_seconds),
                   cell(r.penetration.between_bodies), cell(r.penetration.into_colliders), cell(r.awake)});
  }
  write_file_atomically(folder / "pour_substeps.csv", table.text());
  // The finding in the title: the order p of overlap ~ h^p between the first and last runs,
  // and the fastest run (too few substeps leave a pile jittering awake, so it is not the first).
  size_t fastest = 0;
  for (size_t k = 1; k < results.size(); ++k)
    if (results[k].simulation_seconds < results[fastest].simulation_seconds) fastest = k;
  std::string title = "The fastest run, " + std::to_string(settings.substeps[fastest]) + " substeps (" +
                      fixed(results[fastest].simulation_seconds, 0) + " s), leaves " +
                      fixed(1e3 * results[fastest].penetration.deepest(), 3) + " mm";
  const double first = results.front().penetration.deepest(), last = results.back().penetration.deepest();
  if (results.size() > 1 && first > 0.0 && last > 0.0)
    title = "Overlap falls as h^{" +
            fixed(std::log(first / last) / std::log(double(settings.substeps.back()) / settings.substeps.front()), 1) +
            "}; " + title;
  render_plot(folder, "pour_substeps", R"(set terminal pngcairo size 900,600
set output 'pour_substeps.png'
set datafile separator ','
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'wall time of the pour [s] (log)'
set ylabel 'deepest overlap at the end [m] (log)'
set title ')" + title + R"('
set key right top
plot 'pour_substeps.csv' using 3:4:1 with linespoints pt 7 title 'between grains', \
     '' using 3:4:(sprintf('%d', $1)) with labels offset 1,1 notitle, \
     '' using 3:5 with linespoints pt 5 title 'into the container'
)");
  stop_point();
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"study", "pour-substeps"},
                                  {"count", cell(settings.scene.grains.count)},
                                  {"body", settings.scene.grains.body == xpbd::BodyKind::kRigid ? "rigid" : "soft"},
                                  {"frames", cell(settings.scene.solver.frames)},
                                  {"cohesion", settings.scene.effects.cohesion ? "on" : "off"},
                                  {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
