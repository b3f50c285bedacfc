// A quadratic potential on constraint values, the one shape shared by the elastic energy and
// the Rayleigh dissipation potential of the reference solver:
//
//   Φ(x) = Σ_e [ Σ_r ½ k_er (C_r(x_e) − c_er)² − U0_e ]
//
//   elastic energy  U:  k = 1/α, c = 0, U0 = the rest energy     (DESIGN.md: U = Σ ½ Cᵀα⁻¹C)
//   damping         Ψ:  k = β/h, c = C(xⁿ), U0 = 0               (implicit_solver.hpp)
//
// ∇Φ = Σ k (C − c) ∇C and ∇²Φ = Σ k (∇C ∇Cᵀ + (C − c) ∇²C), computed in the kernel's reduced
// coordinate (constraint_kernels.hpp), projected there when asked, then mapped to x.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fem_reference/constraint_kernels.hpp"
#include "fem_reference/element_form.hpp"

namespace rice::fem {

template <class Kernel>
class ConstraintPotentialForm final : public ElementForm<Kernel::kArity> {
  using Base = ElementForm<Kernel::kArity>;

 public:
  using Constraint = typename Kernel::Constraint;
  using RowVector = Eigen::Matrix<double, Kernel::kRows, 1>;
  using typename Base::LocalMatrix;
  using typename Base::LocalVector;
  using typename Base::Particles;

  /// The form keeps a reference to `constraints`; elements are added with add().
  ConstraintPotentialForm(std::string name, const std::vector<Constraint>& constraints)
      : name_(std::move(name)), constraints_(constraints) {}

  void add(int constraint, const RowVector& stiffness, const RowVector& target, double offset) {
    index_.push_back(constraint);
    stiffness_.push_back(stiffness);
    target_.push_back(target);
    offset_.push_back(offset);
  }

  /// c_e = C(x_e) for every element: the damping potential's state at the start of the step.
  void set_targets(const Positions& x) {
    for (int e = 0; e < element_count(); ++e) target_[e] = evaluate(e, this->gather(x, e), Order::kValue).C;
  }

  std::string name() const override { return name_; }
  int element_count() const override { return static_cast<int>(index_.size()); }
  Particles element_particles(int e) const override { return Kernel::particles(constraint(e)); }

  double element_value(int e, const LocalVector& x) const override {
    const RowVector r = evaluate(e, x, Order::kValue).C - target_[e];
    return 0.5 * r.dot(stiffness_[e].cwiseProduct(r)) - offset_[e];
  }

  LocalVector element_gradient(int e, const LocalVector& x) const override {
    const auto d = evaluate(e, x, Order::kGradient);
    const RowVector force = stiffness_[e].cwiseProduct(d.C - target_[e]);
    return Kernel::expand(constraint(e), (d.dC.transpose() * force).eval());
  }

  LocalMatrix element_hessian(int e, const LocalVector& x, bool project) const override {
    const auto d = evaluate(e, x, Order::kHessian);
    const RowVector& k = stiffness_[e];
    Eigen::Matrix<double, Kernel::kReduced, Kernel::kReduced> H =
        d.dC.transpose() * k.asDiagonal() * d.dC;
    for (int r = 0; r < Kernel::kRows; ++r) H += k[r] * (d.C[r] - target_[e][r]) * d.d2C[r];
    if (project) H = project_to_psd(H);
    return Kernel::expand(constraint(e), H);
  }

 private:
  const Constraint& constraint(int e) const { return constraints_[index_[e]]; }
  typename Kernel::Derivatives evaluate(int e, const LocalVector& x, Order order) const {
    return Kernel::evaluate(constraint(e), Kernel::reduce(constraint(e), x), order);
  }

  std::string name_;
  const std::vector<Constraint>& constraints_;
  std::vector<int> index_;
  std::vector<RowVector> stiffness_, target_;
  std::vector<double> offset_;
};

/// U = Σ ½ Cᵀα⁻¹C − U_rest over `constraints`. Throws std::invalid_argument for a rigid
/// (α = 0) or negative compliance, naming the constraint: the reference needs finite energy.
template <class Kernel>
std::unique_ptr<ConstraintPotentialForm<Kernel>> make_elastic_form(
    const std::string& name, const std::vector<typename Kernel::Constraint>& constraints) {
  auto form = std::make_unique<ConstraintPotentialForm<Kernel>>(name + " elasticity", constraints);
  for (size_t i = 0; i < constraints.size(); ++i) {
    const auto alpha = Kernel::compliance(constraints[i]);
    if (!(alpha.minCoeff() > 0.0))
      throw std::invalid_argument("reference solver: " + name + " constraint " + std::to_string(i) +
                                  " has compliance " + std::to_string(alpha.minCoeff()) +
                                  "; it needs a compliance > 0 (finite stiffness)");
    using Row = typename ConstraintPotentialForm<Kernel>::RowVector;
    form->add(static_cast<int>(i), alpha.cwiseInverse(), Row::Zero(),
              Kernel::rest_energy(constraints[i]));
  }
  return form;
}

/// Ψ = Σ β/(2h) (C(x) − C(xⁿ))² over the constraints with β > 0 (others cost nothing); call
/// set_targets(xⁿ) at the start of each step.
template <class Kernel>
std::unique_ptr<ConstraintPotentialForm<Kernel>> make_damping_form(
    const std::string& name, const std::vector<typename Kernel::Constraint>& constraints, double h) {
  auto form = std::make_unique<ConstraintPotentialForm<Kernel>>(name + " damping", constraints);
  for (size_t i = 0; i < constraints.size(); ++i) {
    const auto beta = Kernel::damping(constraints[i]);
    if (beta.minCoeff() < 0.0)
      throw std::invalid_argument("reference solver: " + name + " constraint " + std::to_string(i) +
                                  " has negative damping " + std::to_string(beta.minCoeff()));
    using Row = typename ConstraintPotentialForm<Kernel>::RowVector;
    if (beta.maxCoeff() > 0.0) form->add(static_cast<int>(i), beta / h, Row::Zero(), 0.0);
  }
  return form;
}

}  // namespace rice::fem
