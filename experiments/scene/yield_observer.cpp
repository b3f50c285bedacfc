// yield.csv; see yield_observer.hpp.
#include "experiments/scene/yield_observer.hpp"

#include "experiments/io/atomic_file.hpp"

namespace rice::experiments {

bool any_collider_yields(const Scene& scene) {
  return any_collider(scene, [](const xpbd::Collider& c) { return xpbd::yields(c); });
}

YieldObserver::YieldObserver(const std::filesystem::path& folder)
    : folder_(folder), rows_({"frame", "time_s", "collider", "offset_m", "force_n", "axis_x", "axis_y", "axis_z"}) {}

void YieldObserver::observe(const World& world, const Stepper& stepper, int frame, double) {
  const std::vector<xpbd::Collider>& colliders = world.model.colliders;
  const std::vector<xpbd::Vec3>& forces = stepper.contacts().collider_forces;
  // The container is the model's collider 0; the rest are numbered as colliders/ draws them.
  for (size_t c = 1; c < colliders.size(); ++c) {
    if (!xpbd::yields(colliders[c])) continue;
    const xpbd::Vec3& axis = colliders[c].yield_axis;
    const double force = c < forces.size() ? forces[c].dot(axis) : 0.0;
    rows_.add_row({cell(frame), cell(stepper.time()), cell(static_cast<long>(c)),
                   cell(xpbd::yield_offset(colliders[c], stepper.time())), cell(force), cell(axis.x()), cell(axis.y()),
                   cell(axis.z())});
  }
  write_file_atomically(folder_ / "yield.csv", rows_.text());
}

void YieldObserver::save_state(xpbd::StateWriter& out) const { out(rows_.rows()); }

void YieldObserver::load_state(xpbd::StateReader& in) {
  std::vector<std::vector<std::string>> rows;
  in(rows);
  rows_.set_rows(std::move(rows));
}

}  // namespace rice::experiments
