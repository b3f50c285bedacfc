// The constraint terms of the reference solver's energy, one form per constraint type:
//
//   Φ(x) = Σ_e [ Σ_r ½ k_er C_r(x_e)² + ½ b_er (C_r(x_e) − c_er)² − U0_e ]
//
// with k = 1/α (the elastic energy U = Σ ½ Cᵀα⁻¹C of DESIGN.md, U0 its rest value) and, in a
// time step, b = β/h, c = C(xⁿ) (the Rayleigh damping potential Ψ of implicit_solver.hpp).
// Both parts share one evaluation of the constraint derivatives per element:
//   ∇Φ = Σ (k C + b (C − c)) ∇C,   ∇²Φ = Σ (k + b) ∇C ∇Cᵀ + (k C + b (C − c)) ∇²C,
// computed in the kernel's reduced coordinate (constraint_kernels.hpp), projected there as
// a whole when asked, then mapped to x.
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

  /// Element for constraints[constraint] with stiffness k, damping b and rest value U0.
  void add(int constraint, const RowVector& stiffness, const RowVector& damping, double offset) {
    index_.push_back(constraint);
    stiffness_.push_back(stiffness);
    damping_.push_back(damping);
    target_.push_back(RowVector::Zero());
    offset_.push_back(offset);
    damped_ = damped_ || damping.maxCoeff() > 0.0;
  }

  /// c_e = C(x_e) for every damped element: the state at the start of the step.
  void set_targets(const Positions& x) {
    if (!damped_) return;
    for (int e = 0; e < element_count(); ++e) target_[e] = evaluate(e, this->gather(x, e), Order::kValue).C;
  }

  std::string name() const override { return name_; }
  int element_count() const override { return static_cast<int>(index_.size()); }
  Particles element_particles(int e) const override { return Kernel::particles(constraint(e)); }

  double element_value(int e, const LocalVector& x) const override {
    const RowVector C = evaluate(e, x, Order::kValue).C;
    const RowVector rate = C - target_[e];
    return 0.5 * C.dot(stiffness_[e].cwiseProduct(C)) + 0.5 * rate.dot(damping_[e].cwiseProduct(rate)) -
           offset_[e];
  }

  LocalVector element_gradient(int e, const LocalVector& x) const override {
    const auto d = evaluate(e, x, Order::kGradient);
    return Kernel::expand(constraint(e), (d.dC.transpose() * force(e, d.C)).eval());
  }

  LocalMatrix element_hessian(int e, const LocalVector& x, bool project) const override {
    const auto d = evaluate(e, x, Order::kHessian);
    const RowVector f = force(e, d.C);
    Eigen::Matrix<double, Kernel::kReduced, Kernel::kReduced> H =
        d.dC.transpose() * (stiffness_[e] + damping_[e]).asDiagonal() * d.dC;
    for (int r = 0; r < Kernel::kRows; ++r) H += f[r] * d.d2C[r];
    if (project) H = project_to_psd(H);
    return Kernel::expand(constraint(e), H);
  }

 private:
  const Constraint& constraint(int e) const { return constraints_[index_[e]]; }
  typename Kernel::Derivatives evaluate(int e, const LocalVector& x, Order order) const {
    return Kernel::evaluate(constraint(e), Kernel::reduce(constraint(e), x), order);
  }
  /// ∂Φ_e/∂C = k C + b (C − c).
  RowVector force(int e, const RowVector& C) const {
    return stiffness_[e].cwiseProduct(C) + damping_[e].cwiseProduct(C - target_[e]);
  }

  std::string name_;
  const std::vector<Constraint>& constraints_;
  std::vector<int> index_;
  std::vector<RowVector> stiffness_, damping_, target_;
  std::vector<double> offset_;
  bool damped_ = false;
};

/// U = Σ ½ Cᵀα⁻¹C − U_rest over `constraints`, plus, when h > 0, the damping potential
/// Ψ = Σ β/(2h) (C(x) − C(xⁿ))² (call set_targets(xⁿ) at the start of each step). Throws
/// std::invalid_argument for a rigid (α = 0) or negative compliance or a negative damping,
/// naming the constraint: the reference needs finite energy.
template <class Kernel>
std::unique_ptr<ConstraintPotentialForm<Kernel>> make_constraint_form(
    const std::string& name, const std::vector<typename Kernel::Constraint>& constraints, double h = 0.0) {
  auto form = std::make_unique<ConstraintPotentialForm<Kernel>>(name, constraints);
  for (size_t i = 0; i < constraints.size(); ++i) {
    const auto alpha = Kernel::compliance(constraints[i]);
    const auto beta = Kernel::damping(constraints[i]);
    if (!(alpha.minCoeff() > 0.0))
      throw std::invalid_argument("reference solver: " + name + " constraint " + std::to_string(i) +
                                  " has compliance " + std::to_string(alpha.minCoeff()) +
                                  "; it needs a compliance > 0 (finite stiffness)");
    if (beta.minCoeff() < 0.0)
      throw std::invalid_argument("reference solver: " + name + " constraint " + std::to_string(i) +
                                  " has negative damping " + std::to_string(beta.minCoeff()));
    using Row = typename ConstraintPotentialForm<Kernel>::RowVector;
    form->add(static_cast<int>(i), alpha.cwiseInverse(), h > 0.0 ? Row(beta / h) : Row::Zero(),
              Kernel::rest_energy(constraints[i]));
  }
  return form;
}

}  // namespace rice::fem
