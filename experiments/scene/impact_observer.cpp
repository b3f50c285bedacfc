// A dropped clump's rebound and deformation; see impact_observer.hpp.
#include "experiments/scene/impact_observer.hpp"

#include <Eigen/SVD>

#include <algorithm>
#include <limits>

#include "experiments/io/csv_table.hpp"

namespace rice::experiments {

void ImpactObserver::begin(const World& world) {
  const xpbd::Model& model = world.model;
  // Bodies own consecutive particles, in order: a tet's grain is the last body starting at or
  // before its first particle.
  std::vector<int> first;
  for (const xpbd::Body& body : model.bodies) first.push_back(body.first_particle);
  for (const xpbd::NeoHookeanTet& tet : model.neo_hookean) {
    const auto after = std::upper_bound(first.begin(), first.end(), tet.particles[0]);
    body_of_tet_.push_back(static_cast<int>(after - first.begin()) - 1);
  }
  lowest_.assign(world.count(), std::numeric_limits<double>::infinity());
  rebound_.assign(world.count(), 0.0);
}

double ImpactObserver::mean_principal_strain(const World& world) const {
  const xpbd::Model& model = world.model;
  double strain = 0.0, volume = 0.0;
  for (size_t t = 0; t < model.neo_hookean.size(); ++t) {
    if (body_of_tet_[t] >= world.released) continue;
    const xpbd::NeoHookeanTet& tet = model.neo_hookean[t];
    const auto x = [&](int k) { return model.particles.x.row(tet.particles[k]).transpose(); };
    xpbd::Mat3 Ds;
    Ds << x(1) - x(0), x(2) - x(0), x(3) - x(0);
    const Eigen::Vector3d sigma = Eigen::JacobiSVD<xpbd::Mat3>(Ds * tet.Dm_inv).singularValues();
    strain += tet.rest_volume * (sigma.array() - 1.0).abs().maxCoeff();
    volume += tet.rest_volume;
  }
  return volume > 0.0 ? strain / volume : 0.0;
}

void ImpactObserver::observe(const World& world, const Stepper&, int frame, double) {
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

}  // namespace rice::experiments
