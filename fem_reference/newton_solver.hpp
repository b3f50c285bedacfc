// Minimises E(x) = Σ w_f · form_f(x) over the free DOFs with Newton's method: per-element PSD
// projection of the Hessian, CHOLMOD supernodal Cholesky (symbolic analysis once, numeric
// factorisation per step), backtracking line search with the Armijo condition, and
// fall-backs when a step fails (Nocedal & Wright, "Numerical Optimization", §3.1, §3.4):
//
//   1. the factorisation fails or the direction is not a descent direction
//        → shift the diagonal by τ (τ = 1e-8·mean diag, ×100 per retry, 4 retries);
//   2. the line search finds no acceptable step → one Jacobi-scaled gradient step,
//        d = −diag(H)⁻¹ ∇E, with line search;
//   3. if that fails too, stop ("stalled"): converged if Newton's correction ‖d‖∞ is below
//      1e-8 ‖x‖∞, not converged otherwise.
// Where a trial step's predicted decrease is below the energy's round-off (near the solution,
// or when large loads or rest energies sit in E), the line search accepts a step that lowers
// ‖∇E‖ instead, since E can no longer tell better from worse.
//
// Stopping test: ‖∇E‖₂ ≤ tolerance · s, with s = Σ_f ‖w_f ∇form_f(x₀)‖₂ the size of the terms
// that must balance at the solution (the problem's own force scale, in the units of ∇E); or a
// Newton step below round-off, ‖d‖∞ ≤ 1e-14 ‖x‖∞, when the tolerance asks for more digits
// than the terms' round-off leaves (the inertia term m x carries an error of ε m |x|).
#pragma once

#include <Eigen/CholmodSupport>
#include <memory>
#include <vector>

#include "fem_reference/dof_map.hpp"
#include "fem_reference/form.hpp"
#include "fem_reference/sparse_hessian.hpp"

namespace rice::fem {

struct NewtonSettings {
  double tolerance = 1e-9;  ///< relative gradient tolerance (see the file comment)
  int max_iterations = 100;
  bool project_hessians = true;
  double armijo = 1e-4;     ///< sufficient-decrease constant c₁
  int max_backtracks = 30;  ///< halvings of the step before the line search gives up
};

/// Wall time spent in each part of the Newton loop [s], summed over its iterations.
struct NewtonTimings {
  double assembly = 0.0;       ///< gradient and Hessian assembly
  double analysis = 0.0;       ///< CHOLMOD symbolic analysis (once per solver)
  double factorization = 0.0;  ///< CHOLMOD numeric factorisation
  double solve = 0.0;          ///< triangular solves
  double line_search = 0.0;    ///< energy evaluations of the line search
};

struct NewtonReport {
  bool converged = false;
  int iterations = 0;         ///< Newton (or fall-back) steps taken
  int regularized_steps = 0;  ///< steps whose matrix needed a diagonal shift
  int gradient_steps = 0;     ///< steps that fell back to a gradient step
  bool stalled = false;       ///< ended because no step lowered E or ‖∇E‖ measurably
  double energy = 0.0;        ///< E at the end
  double gradient_norm = 0.0; ///< ‖∇E‖₂ over the free DOFs at the end
  double gradient_scale = 0.0;///< s of the stopping test
  NewtonTimings seconds;
};

struct WeightedForm {
  const Form* form;
  double weight;
};

class NewtonSolver {
 public:
  /// `fixed[i]` removes particle i's DOFs. The forms must outlive the solver.
  NewtonSolver(std::vector<WeightedForm> forms, const std::vector<bool>& fixed,
               const NewtonSettings& settings);

  /// Minimises E starting from x; fixed particles keep their rows of x.
  NewtonReport minimize(Positions& x);

  double energy(const Positions& x) const;
  /// ∇E over the free DOFs.
  Eigen::VectorXd gradient(const Positions& x) const;

 private:
  std::vector<Stencils> collect_stencils() const;
  void assemble_hessian(const Positions& x);
  /// Factorises the assembled Hessian, shifting its diagonal when that fails; false if no
  /// shift helped.
  bool factorize(NewtonReport& report);
  /// Backtracking Armijo search along d from x; on success moves x and returns true.
  bool line_search(Positions& x, double energy, const Eigen::VectorXd& g, const Eigen::VectorXd& d,
                   NewtonReport& report) const;

  /// Σ_f |w_f form_f(x)|, the scale of E's round-off.
  double magnitude(const Positions& x) const;

  std::vector<WeightedForm> forms_;
  NewtonSettings settings_;
  DofMap dofs_;
  SparseHessian hessian_;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt_;
  bool analyzed_ = false;
};

}  // namespace rice::fem
