// The inertia term of backward Euler's incremental potential, ½ ‖x − x̂‖²_M with lumped
// masses M and x̂ = xⁿ + h vⁿ (external loads enter through load_form.hpp instead of x̂).
// One element per free particle; pinned particles (infinite mass) have none.
#pragma once

#include <vector>

#include "fem_reference/element_form.hpp"

namespace rice::fem {

class InertiaForm final : public ElementForm<1> {
 public:
  /// Masses 1/w of the particles with w > 0.
  explicit InertiaForm(const Eigen::VectorXd& inverse_masses) {
    for (int i = 0; i < inverse_masses.size(); ++i)
      if (inverse_masses[i] > 0.0) {
        particle_.push_back(i);
        mass_.push_back(1.0 / inverse_masses[i]);
      }
    target_.setZero(inverse_masses.size(), 3);
  }

  /// x̂, #P by 3.
  void set_target(const Positions& target) { target_ = target; }

  std::string name() const override { return "inertia"; }
  int element_count() const override { return static_cast<int>(particle_.size()); }
  Particles element_particles(int e) const override { return {particle_[e]}; }
  double element_value(int e, const LocalVector& x) const override {
    return 0.5 * mass_[e] * (x - target_.row(particle_[e]).transpose()).squaredNorm();
  }
  LocalVector element_gradient(int e, const LocalVector& x) const override {
    return mass_[e] * (x - target_.row(particle_[e]).transpose());
  }
  LocalMatrix element_hessian(int e, const LocalVector&, bool) const override {
    return mass_[e] * LocalMatrix::Identity();
  }

 private:
  std::vector<int> particle_;
  std::vector<double> mass_;
  Positions target_;
};

}  // namespace rice::fem
