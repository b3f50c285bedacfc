// Newton's method with CHOLMOD, line search and fall-backs; see newton_solver.hpp.
#include "fem_reference/newton_solver.hpp"

#include <chrono>
#include <cmath>
#include <limits>

namespace rice::fem {
namespace {

using Clock = std::chrono::steady_clock;

/// A Newton step shorter than this fraction of max |x| cannot change x in double precision
/// beyond a few ulps: the solve has converged as far as round-off allows.
constexpr double kRoundOff = 1e-14;

/// Energy changes below this fraction of Σ|w_f form_f| are taken as round-off: an element's
/// energy is often a difference of much larger terms (the Neo-Hookean rest energy), so the
/// noise sits far above machine epsilon times |E|.
constexpr double kEnergyRoundOff = 1e-8;

/// When the search stalls (neither E nor ‖∇E‖ can be lowered measurably, which the projected
/// Hessian of strongly deformed tets allows), the solve still counts as converged if Newton's
/// correction is below this fraction of max |x|: far below any error the studies measure.
constexpr double kStallTolerance = 1e-8;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

NewtonSolver::NewtonSolver(std::vector<WeightedForm> forms, const std::vector<bool>& fixed,
                           const NewtonSettings& settings)
    : forms_(std::move(forms)), settings_(settings), dofs_(fixed),
      hessian_(dofs_, collect_stencils()) {
  llt_.cholmod().print = 0;  // a failed factorisation is handled (and counted) by the fall-back
  if (!(settings.tolerance > 0.0) || settings.max_iterations < 1 || !(settings.armijo > 0.0) ||
      !(settings.armijo < 1.0) || settings.max_backtracks < 1)
    throw std::invalid_argument("NewtonSolver: need tolerance > 0, max_iterations >= 1, "
                                "0 < armijo < 1, max_backtracks >= 1");
}

std::vector<Stencils> NewtonSolver::collect_stencils() const {
  std::vector<Stencils> stencils;
  for (const WeightedForm& f : forms_) stencils.push_back(f.form->stencils());
  return stencils;
}

double NewtonSolver::energy(const Positions& x) const {
  double e = 0.0;
  for (const WeightedForm& f : forms_) e += f.weight * f.form->value(x);
  return e;
}

Eigen::VectorXd NewtonSolver::gradient(const Positions& x) const {
  Positions g = Positions::Zero(x.rows(), 3);
  for (const WeightedForm& f : forms_) f.form->add_gradient(x, f.weight, g);
  return dofs_.gather(g);
}

void NewtonSolver::assemble_hessian(const Positions& x) {
  hessian_.set_zero();
  for (const WeightedForm& f : forms_)
    f.form->add_hessian(x, f.weight, settings_.project_hessians, hessian_);
}

bool NewtonSolver::factorize(NewtonReport& report) {
  if (!analyzed_) {
    const auto start = Clock::now();
    llt_.analyzePattern(hessian_.matrix());
    report.seconds.analysis += seconds_since(start);
    analyzed_ = true;
  }
  const double mean_diagonal = hessian_.diagonal().cwiseAbs().mean();
  double shift = 1e-8 * (mean_diagonal > 0.0 ? mean_diagonal : 1.0), applied = 0.0;
  for (int attempt = 0; attempt <= 4; ++attempt) {
    const auto start = Clock::now();
    llt_.factorize(hessian_.matrix());
    report.seconds.factorization += seconds_since(start);
    if (llt_.info() == Eigen::Success) {
      if (applied > 0.0) ++report.regularized_steps;
      return true;
    }
    hessian_.add_to_diagonal(shift - applied);  // total shift on the diagonal becomes `shift`
    applied = shift;
    shift *= 100.0;
  }
  return false;
}

bool NewtonSolver::line_search(Positions& x, double energy0, const Eigen::VectorXd& g,
                               const Eigen::VectorXd& d, NewtonReport& report) const {
  const auto start = Clock::now();
  const double slope = g.dot(d);  // < 0 for a descent direction
  const double noise = kEnergyRoundOff * magnitude(x);
  const double gradient_norm = g.norm();
  // Start no farther than every form allows (the contact barrier: nothing crosses a surface).
  Positions direction = Positions::Zero(x.rows(), 3);
  dofs_.scatter_add(d, 1.0, direction);
  double step = 1.0;
  for (const WeightedForm& f : forms_) step = std::min(step, f.form->max_step(x, direction));
  Positions trial = x;
  bool accepted = false;
  for (int k = 0; k < settings_.max_backtracks && !accepted; ++k, step *= 0.5) {
    trial = x;
    dofs_.scatter_add(d, step, trial);
    const double e = energy(trial);
    if (!std::isfinite(e)) continue;
    if (-step * slope > noise) accepted = e <= energy0 + settings_.armijo * step * slope;
    else accepted = gradient(trial).norm() < gradient_norm;  // E cannot tell; ∇E can
  }
  if (accepted) x = trial;
  report.seconds.line_search += seconds_since(start);
  return accepted;
}

double NewtonSolver::magnitude(const Positions& x) const {
  double sum = 0.0;
  for (const WeightedForm& f : forms_) sum += std::abs(f.weight * f.form->value(x));
  return sum;
}

NewtonReport NewtonSolver::minimize(Positions& x) {
  NewtonReport report;
  if (dofs_.dof_count() == 0) {
    report.converged = true;
    report.energy = energy(x);
    return report;
  }
  // ∇E at the start, term by term: the terms' sizes make the scale of the stopping test.
  auto assemble_start = Clock::now();
  Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs_.dof_count());
  for (const WeightedForm& f : forms_) {
    Positions term = Positions::Zero(x.rows(), 3);
    f.form->add_gradient(x, f.weight, term);
    const Eigen::VectorXd free_term = dofs_.gather(term);
    report.gradient_scale += free_term.norm();
    g += free_term;
  }
  report.seconds.assembly += seconds_since(assemble_start);
  const double tolerance = settings_.tolerance * report.gradient_scale;
  double e = energy(x);
  for (; report.iterations < settings_.max_iterations; ++report.iterations) {
    if (!g.allFinite() || !std::isfinite(e)) break;
    if (g.norm() <= tolerance) {
      report.converged = true;
      break;
    }
    assemble_start = Clock::now();
    assemble_hessian(x);
    report.seconds.assembly += seconds_since(assemble_start);

    bool moved = false;
    double newton_step = std::numeric_limits<double>::infinity();  // ‖d‖∞
    const double x_magnitude = dofs_.gather(x).lpNorm<Eigen::Infinity>();
    if (factorize(report)) {
      const auto solve_start = Clock::now();
      const Eigen::VectorXd d = -llt_.solve(g);
      report.seconds.solve += seconds_since(solve_start);
      if (d.allFinite()) newton_step = d.lpNorm<Eigen::Infinity>();
      if (newton_step <= kRoundOff * x_magnitude) {
        report.converged = true;  // the remaining correction is below round-off of x
        break;
      }
      if (d.allFinite() && g.dot(d) < 0.0) moved = line_search(x, e, g, d, report);
    }
    if (!moved) {  // fall-back: Jacobi-scaled gradient step
      const Eigen::VectorXd diagonal = hessian_.diagonal().cwiseAbs().cwiseMax(1e-300);
      const Eigen::VectorXd d = -g.cwiseQuotient(diagonal);
      ++report.gradient_steps;
      if (!line_search(x, e, g, d, report)) {
        // No step lowers E or ‖∇E‖ measurably: accept x if Newton's correction is negligible.
        report.stalled = true;
        report.converged = newton_step <= kStallTolerance * x_magnitude;
        break;
      }
    }
    assemble_start = Clock::now();
    g = gradient(x);
    report.seconds.assembly += seconds_since(assemble_start);
    e = energy(x);
  }
  if (!report.converged && !report.stalled && g.allFinite() && g.norm() <= tolerance) report.converged = true;
  report.energy = e;
  report.gradient_norm = g.norm();
  return report;
}

}  // namespace rice::fem
