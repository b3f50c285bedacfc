// The pile at the end of a run; see pile_observer.hpp.
#include "experiments/scene/pile_observer.hpp"

#include <cmath>
#include <iostream>
#include <limits>
#include <optional>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/pile/pile_measures.hpp"
#include "experiments/pile/pile_plot.hpp"

namespace rice::experiments {

void PileObserver::end(const World& world, const Stepper&, SceneReport& report) {
  const std::vector<xpbd::Vec3> centres = world.released_centres();
  CsvTable final_centres({"grain", "x", "y", "z", "r"});
  for (size_t g = 0; g < centres.size(); ++g) {
    const xpbd::Vec3& c = centres[g];
    final_centres.add_row({cell(static_cast<long>(g)), cell(c.x()), cell(c.y()), cell(c.z()), cell(std::hypot(c.x(), c.y()))});
  }
  write_file_atomically(folder_ / "final_centres.csv", final_centres.text());
  SceneResult& r = report.result;
  r.footprint_radius = footprint_radius(centres);
  r.clusters = count_clusters(world.model, 1e-4);
  r.top = world.top();
  r.released = world.released;
  r.grain_length = world.grain_length;
  const std::optional<HeapProfile> fitted =
      write_pile_plot(folder_, centres,
                      {.holder = holder_, .cohesion = cohesion_, .rim_radius = world.bowl.rim_radius,
                       .ring_width = 0.5 * world.grain_length});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.angle_of_repose_degrees = fitted ? fitted->angle_degrees : nan;
  r.heap_height = fitted ? fitted->apex_height : nan;
  if (fitted)
    std::cout << "rice run: angle of repose " << fixed(r.angle_of_repose_degrees, 1) << " degrees, heap "
              << fixed(1e3 * r.heap_height, 1) << " mm high\n";
  report.info.push_back({"angle_of_repose_deg", fitted ? cell(r.angle_of_repose_degrees) : "n/a"});
  report.info.push_back({"heap_height_m", fitted ? cell(r.heap_height) : "n/a"});
  report.info.push_back({"footprint_radius_m", cell(r.footprint_radius)});
  report.info.push_back({"clusters", cell(r.clusters)});
  report.info.push_back({"top_centre_at_end_m", cell(r.top)});
}

}  // namespace rice::experiments
