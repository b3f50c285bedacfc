// stats.csv; see stats_observer.hpp.
#include "experiments/scene/stats_observer.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "experiments/io/atomic_file.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/model_health.hpp"

namespace rice::experiments {
namespace {

long awake_grains(const World& world) {
  return std::count_if(world.model.bodies.begin(), world.model.bodies.end(),
                       [](const xpbd::Body& b) { return !b.asleep; });
}

/// The most tets inverted at any frame's end and the smallest det F of any, from the table's rows.
std::pair<long, double> worst_tets_over_frames(const CsvTable& stats) {
  const size_t inverted = stats.column("inverted_tets"), smallest = stats.column("smallest_volume_ratio");
  long most = 0;
  double least = INFINITY;
  for (const std::vector<std::string>& row : stats.rows()) {
    most = std::max(most, std::stol(row[inverted]));
    least = std::fmin(least, std::stod(row[smallest]));
  }
  return {most, least};
}

}  // namespace

StatsObserver::StatsObserver(const std::filesystem::path& folder)
    : folder_(folder),
      stats_({"frame", "time_s", "wall_s", "awake", "candidates", "contacts", "bonds", "bonds_broken",
              "max_penetration_m", "kinetic_energy_j", "top_m", "inverted_tets", "smallest_volume_ratio",
              "broad_phase_s", "narrow_phase_s", "solve_s", "sleeping_s"}) {}

void StatsObserver::begin(const World& world) {
  for (const xpbd::Collider& c : world.model.colliders) first_removal_ = std::min(first_removal_, c.removal_time);
}

void StatsObserver::observe(const World& world, const Stepper& stepper, int frame, double wall_seconds) {
  const xpbd::ContactStatistics& contact = stepper.contacts();
  const xpbd::SolverTimings& t = stepper.timings();
  const double top = world.top();
  if (stepper.time() <= first_removal_) top_before_removal_ = top;
  // One pass over the tets a frame, where the solve makes one or more each substep.
  const xpbd::TetVolumeRatios tets = xpbd::tet_volume_ratios(world.model);
  stats_.add_row({cell(frame), cell(stepper.time()), cell(wall_seconds), cell(awake_grains(world)),
                  cell(contact.candidates), cell(contact.contacts), cell(contact.bonds), cell(contact.bonds_broken),
                  cell(contact.max_penetration), cell(xpbd::kinetic_energy(world.model)), cell(top),
                  cell(tets.inverted), cell(tets.smallest), cell(t.broad_phase), cell(t.narrow_phase), cell(t.solve()),
                  cell(t.sleeping)});
  // Each frame, so that a run stopped hours in (killed, or out of time) shows where its time
  // went; a few kB a frame.
  write_file_atomically(folder_ / "stats.csv", stats_.text());
}

void StatsObserver::end(const World& world, const Stepper& stepper, SceneReport& report) {
  write_file_atomically(folder_ / "stats.csv", stats_.text());
  SceneResult& r = report.result;
  r.awake = static_cast<int>(awake_grains(world));
  r.kinetic_energy = xpbd::kinetic_energy(world.model);
  r.penetration = xpbd::deepest_penetration(world.model, stepper.time());
  r.finite = xpbd::state_finite(world.model);
  r.inverted_tets = xpbd::inverted_tets(world.model);
  r.grain_thickness = world.grain_thickness;
  const bool removed = std::isfinite(first_removal_);
  r.top_before_removal = removed ? top_before_removal_ : std::numeric_limits<double>::quiet_NaN();
  report.info.push_back({"awake_at_end", cell(r.awake)});
  report.info.push_back({"top_centre_before_removal_m", removed ? cell(r.top_before_removal) : "n/a"});
  report.info.push_back({"penetration_between_grains_at_end_m", cell(r.penetration.between_bodies)});
  report.info.push_back({"penetration_into_container_at_end_m", cell(r.penetration.into_colliders)});
  report.info.push_back({"grain_thickness_m", cell(r.grain_thickness)});
  report.info.push_back({"state_finite_at_end", r.finite ? "yes" : "no"});
  report.info.push_back({"inverted_tets_at_end", world.model.neo_hookean.empty() ? "n/a" : cell(r.inverted_tets)});
  if (world.model.neo_hookean.empty()) return;
  const auto [most_inverted, smallest] = worst_tets_over_frames(stats_);
  report.info.push_back({"inverted_tets_most_in_a_frame", cell(most_inverted)});
  report.info.push_back({"smallest_volume_ratio_over_frames", cell(smallest)});
}

void StatsObserver::save_state(xpbd::StateWriter& out) const { out(stats_.rows(), top_before_removal_); }

void StatsObserver::load_state(xpbd::StateReader& in) {
  std::vector<std::vector<std::string>> rows;
  in(rows, top_before_removal_);
  stats_.set_rows(std::move(rows));
}

}  // namespace rice::experiments
