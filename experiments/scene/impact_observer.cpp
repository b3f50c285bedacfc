// A dropped clump's rebound and deformation; see impact_observer.hpp.
#include "experiments/scene/impact_observer.hpp"

#include <Eigen/SVD>

#include <algorithm>
#include <limits>

#include "experiments/io/csv_table.hpp"
#include "experiments/scene/stepper.hpp"
#include "xpbd/body.hpp"
#include "xpbd/tet_stencil.hpp"

namespace rice::experiments {

void ImpactObserver::begin(const World& world) {
  const std::vector<int> owner = xpbd::soft_body_of_particle(world.model);
  for (const xpbd::NeoHookeanTet& tet : world.model.neo_hookean) body_of_tet_.push_back(owner[tet.particles[0]]);
  lowest_.assign(world.count(), std::numeric_limits<double>::infinity());
  rebound_.assign(world.count(), 0.0);
}

double ImpactObserver::mean_principal_strain(const World& world) const {
  const xpbd::Model& model = world.model;
  double strain = 0.0, volume = 0.0;
  for (size_t t = 0; t < model.neo_hookean.size(); ++t) {
    if (body_of_tet_[t] >= world.released) continue;
    const xpbd::NeoHookeanTet& tet = model.neo_hookean[t];
    const auto x = [&](int k) -> xpbd::Vec3 { return model.particles.x.row(tet.particles[k]).transpose(); };
    const xpbd::Mat3 F = xpbd::edge_matrix(x(0), x(1), x(2), x(3)) * tet.Dm_inv;  // F = D_s D_m⁻¹
    const Eigen::Vector3d sigma = Eigen::JacobiSVD<xpbd::Mat3>(F).singularValues();
    strain += tet.rest_volume * (sigma.array() - 1.0).abs().maxCoeff();
    volume += tet.rest_volume;
  }
  return volume > 0.0 ? strain / volume : 0.0;
}

void ImpactObserver::observe(const World& world, const Stepper& stepper, int frame, double) {
  if (stepper.time() < drop_time_) return;
  for (int g = 0; g < world.released; ++g) {
    const double z = world.centre(g).z();
    lowest_[g] = std::min(lowest_[g], z);
    rebound_[g] = std::max(rebound_[g], z - lowest_[g]);
  }
  if (body_of_tet_.empty()) return;
  const double strain = mean_principal_strain(world);
  if (strain > peak_strain_) peak_strain_ = strain, peak_frame_ = frame;
}

void ImpactObserver::end(const World& world, const Stepper&, SceneReport& report) {
  double sum = 0.0;
  for (int g = 0; g < world.released; ++g) sum += rebound_[g];
  SceneResult& r = report.result;
  r.rebound_height = world.released > 0 ? sum / world.released : 0.0;
  r.peak_strain = body_of_tet_.empty() ? std::numeric_limits<double>::quiet_NaN() : peak_strain_;
  report.info.push_back({"rebound_height_m", cell(r.rebound_height)});
  report.info.push_back({"peak_principal_strain", body_of_tet_.empty() ? "n/a" : cell(r.peak_strain)});
  report.info.push_back({"peak_principal_strain_frame", body_of_tet_.empty() ? "n/a" : cell(peak_frame_)});
}

void ImpactObserver::save_state(xpbd::StateWriter& out) const { out(lowest_, rebound_, peak_strain_, peak_frame_); }
void ImpactObserver::load_state(xpbd::StateReader& in) { in(lowest_, rebound_, peak_strain_, peak_frame_); }

}  // namespace rice::experiments
