// Paper Fig. 10 by the drop scene at three soak times; see figure10.hpp.
#include "experiments/figures/figure10.hpp"

#include <cstdio>
#include <stdexcept>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_run.hpp"

namespace rice::experiments {

void validate(const Figure10Settings& s) {
  if (s.soak_minutes.empty()) throw std::invalid_argument("figure 10: give at least one soak time");
  for (const double m : s.soak_minutes)
    if (!(m > 0.0 && m <= 1e5)) throw std::invalid_argument("figure 10: soak times must be in (0, 1e5] minutes");
}

void figure10_command(const Figure10Settings& s, const std::filesystem::path& folder) {
  validate(s);
  const auto overrides_for = [&](double minutes) {
    std::vector<std::string> overrides = s.overrides;
    overrides.push_back("grains.soak_minutes=" + cell(minutes));
    return overrides;
  };
  for (const double minutes : s.soak_minutes) validate(read_scene_file(s.scene, overrides_for(minutes)));
  make_output_folder(folder);  // only once every run's scene reads
  CsvTable table({"soak_minutes", "footprint_radius_m", "clusters", "rebound_height_m", "peak_principal_strain",
                  "awake_at_end", "simulation_s", "heap_height_m"});
  std::vector<SceneResult> results;
  for (const double minutes : s.soak_minutes) {
    const SceneResult r =
        run_scene_command(s.scene, overrides_for(minutes), folder / ("soak_" + cell(minutes) + "min"));
    table.add_row({cell(minutes), cell(r.footprint_radius), cell(r.clusters), cell(r.rebound_height),
                   cell(r.peak_strain), cell(r.awake), cell(r.simulation_seconds), cell(r.heap_height)});
    results.push_back(r);
  }
  write_file_atomically(folder / "figure10.csv", table.text());
  const std::string title = "Soaked " + cell(s.soak_minutes.front()) + " to " + cell(s.soak_minutes.back()) +
                            " min: footprint " + fixed(1e3 * results.front().footprint_radius, 1) + " to " +
                            fixed(1e3 * results.back().footprint_radius, 1) + " mm, " +
                            std::to_string(results.front().clusters) + " to " + std::to_string(results.back().clusters) +
                            " groups of touching grains, heap " + fixed(1e3 * results.front().heap_height, 1) + " to " +
                            fixed(1e3 * results.back().heap_height, 1) + " mm high";
  std::printf("%s\n", title.c_str());
  render_plot(folder, "figure10", csv_plot_header("figure10", 2000, 500) + "set multiplot layout 1,5 title '" + title +
                                      "'\n" + R"(set logscale x 10
set format x '10^{%L}'
set xlabel 'soak time [min]'
set ylabel 'radius holding 90% of the grains [mm]'
plot 'figure10.csv' using 1:($2*1e3) with linespoints pt 7 lw 2 notitle
set ylabel 'groups of touching grains'
plot 'figure10.csv' using 1:3 with linespoints pt 7 lw 2 notitle
set ylabel 'heap apex above the lowest centre [mm]'
plot 'figure10.csv' using 1:($8*1e3) with linespoints pt 7 lw 2 notitle
set ylabel 'mean rebound of a grain [mm]'
plot 'figure10.csv' using 1:($4*1e3) with linespoints pt 7 lw 2 notitle
set ylabel 'largest mean principal strain (soft grains)'
plot 'figure10.csv' using 1:5 with linespoints pt 7 lw 2 notitle
unset multiplot
)");
}

}  // namespace rice::experiments
