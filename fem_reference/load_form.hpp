// The potential of constant external loads, −Σ fᵢ·xᵢ with fᵢ = mᵢ g + f_ext,i (gravity and the
// model's external forces) over free particles. Linear in x: its Hessian is zero.
#pragma once

#include <vector>

#include "fem_reference/element_form.hpp"
#include "xpbd/model.hpp"

namespace rice::fem {

class LoadForm final : public ElementForm<1> {
 public:
  explicit LoadForm(const xpbd::Model& model) {
    const Eigen::VectorXd& w = model.particles.w;
    const bool has_forces = model.external_forces.rows() != 0;
    for (int i = 0; i < w.size(); ++i) {
      if (w[i] <= 0.0) continue;
      xpbd::Vec3 f = model.gravity / w[i];
      if (has_forces) f += model.external_forces.row(i).transpose();
      if (f.isZero()) continue;
      particle_.push_back(i);
      force_.push_back(f);
    }
  }

  std::string name() const override { return "loads"; }
  int element_count() const override { return static_cast<int>(particle_.size()); }
  Particles element_particles(int e) const override { return {particle_[e]}; }
  double element_value(int e, const LocalVector& x) const override { return -force_[e].dot(x); }
  LocalVector element_gradient(int e, const LocalVector&) const override { return -force_[e]; }
  LocalMatrix element_hessian(int, const LocalVector&, bool) const override {
    return LocalMatrix::Zero();
  }
  void add_hessian(const Positions&, double, bool, SparseHessian&) const override {}

 private:
  std::vector<int> particle_;
  std::vector<xpbd::Vec3> force_;
};

}  // namespace rice::fem
