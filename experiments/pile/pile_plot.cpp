// pile.png of a pour; see pile_plot.hpp.
#include "experiments/pile/pile_plot.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"

namespace rice::experiments {
namespace {

/// The side view's gnuplot size and title: to scale, unless the grains lie in a layer under a
/// quarter as high as it is wide (a pot's), whose scale left its height a line of ticks.
std::string side_view_size(const std::vector<xpbd::Vec3>& centres) {
  xpbd::Vec3 lower = xpbd::Vec3::Constant(INFINITY), upper = -lower;
  for (const xpbd::Vec3& c : centres) lower = lower.cwiseMin(c), upper = upper.cwiseMax(c);
  const bool layer = !centres.empty() && upper.z() - lower.z() < 0.25 * (upper.x() - lower.x());
  return layer ? "set size noratio\nset title 'From the side (height stretched)'" : "set title 'From the side'";
}

}  // namespace

std::optional<HeapProfile> write_pile_plot(const std::filesystem::path& folder, const std::vector<xpbd::Vec3>& centres,
                                           const PilePlotSettings& settings) {
  const std::string top_and_side = R"(set terminal pngcairo size 1200,560
set output 'pile.png'
set datafile separator ','
set multiplot layout 1,2
set size ratio -1
set xlabel 'x [m]'
set ylabel 'y [m]'
)";
  if (settings.holder == PileHolder::kBowl) {
    const std::string rim = cell(settings.rim_radius);
    render_plot(folder, "pile", top_and_side + R"(set title 'The pile from the top (grain centres; the rim)'
set parametric
plot [0:2*pi] )" + rim + "*cos(t), " + rim + R"(*sin(t) with lines lc rgb 'gray' notitle, \
     'final_centres.csv' using 2:3 with points pt 7 ps 0.5 notitle
unset parametric
set xlabel 'x [m]'
set ylabel 'z [m]'
set title 'The pile from the side (grain centres; the inside wall)'
plot 'bowl_outline.csv' using 1:2 with lines lc rgb 'gray' notitle, \
     'final_centres.csv' using 2:4 with points pt 7 ps 0.5 notitle
unset multiplot
)");
    return std::nullopt;
  }
  std::optional<HeapProfile> fitted;
  if (settings.holder == PileHolder::kPlate) {
    try {
      fitted = heap_profile(centres, settings.ring_width);
    } catch (const std::invalid_argument&) {
      // Grains scattered one deep (a dry clump dropped): no flank to fit.
    }
  }
  if (!fitted) {
    const std::string what = settings.holder == PileHolder::kMould
                                 ? "The grains in the mould from the top (centres)"
                                 : "The grains from the top (centres): scattered, no heap";
    render_plot(folder, "pile", top_and_side + "set title '" + what + R"('
plot 'final_centres.csv' using 2:3 with points pt 7 ps 0.5 notitle
set xlabel 'x [m]'
set ylabel 'z [m]'
)" + side_view_size(centres) + R"(
plot 'final_centres.csv' using 2:4 with points pt 7 ps 0.5 notitle
unset multiplot
)");
    return std::nullopt;
  }
  const HeapProfile& heap = *fitted;
  CsvTable rings({"radius_m", "height_m", "on_flank"});
  for (size_t k = 0; k < heap.ring_radius.size(); ++k)
    rings.add_row({cell(heap.ring_radius[k]), cell(heap.ring_height[k]), cell(heap.on_flank[k] ? 1 : 0)});
  write_file_atomically(folder / "heap_profile.csv", rings.text());
  const std::string title = "Angle of repose " + fixed(heap.angle_degrees, 1) + " degrees (" +
                            (settings.cohesion ? "with" : "without") + " cohesion)";
  render_plot(folder, "pile", top_and_side + R"(set title 'The heap from the top (grain centres)'
plot 'final_centres.csv' using 2:3 with points pt 7 ps 0.5 notitle
set size noratio
set xlabel 'distance from the axis [m]'
set ylabel 'height above the lowest centre [m]'
set yrange [0:*]
set title ')" + title + R"('
plot 'heap_profile.csv' using 1:($3 == 1 ? $2 : 1/0) with points pt 7 title 'highest centre of a ring: flank', \
     'heap_profile.csv' using 1:($3 == 0 ? $2 : 1/0) with points pt 6 title 'apex and toe', \
     )" + cell(heap.intercept) + " + " + cell(heap.slope) + R"(*x with lines lc rgb 'black' title 'least-squares flank'
unset multiplot
)");
  return fitted;
}

}  // namespace rice::experiments
