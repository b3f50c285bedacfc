// Backward Euler and quasi-static solves of the shared model; see implicit_solver.hpp.
#include "fem_reference/implicit_solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "xpbd/solver.hpp"

namespace rice::fem {
namespace {

template <class ConcreteForm>
void append_if_used(std::vector<WeightedForm>& forms, const ConcreteForm* form, double weight) {
  if (form && form->element_count() > 0) forms.push_back({form, weight});
}

}  // namespace

ImplicitSolver::ImplicitSolver(xpbd::Model& model, const ImplicitSettings& settings, const BarrierSettings& contact)
    : model_(model), settings_(settings), inertia_(model.particles.w), loads_(model) {
  const xpbd::Particles& p = model.particles;
  if (p.v.rows() != p.x.rows() || p.w.size() != p.x.rows())
    throw std::invalid_argument("reference solver: particles have " + std::to_string(p.x.rows()) +
                                " positions, " + std::to_string(p.v.rows()) + " velocities, " +
                                std::to_string(p.w.size()) + " inverse masses");
  if (!(settings.time_step > 0.0))
    throw std::invalid_argument("reference solver: time_step must be > 0");
  fixed_.resize(p.size());
  for (int i = 0; i < p.size(); ++i) fixed_[i] = !(p.w[i] > 0.0);
  for (const xpbd::Attachment& a : model.attachments) {
    if (a.particle < 0 || a.particle >= p.size())
      throw std::invalid_argument("reference solver: attachment names particle " +
                                  std::to_string(a.particle));
    if (a.compliance == 0.0) fixed_[a.particle] = true;  // a Dirichlet condition
    else compliant_attachments_.push_back(a);
  }
  hold_rigid_attachments();

  // Weights of eq. (1); forms without elements are left out, so unused effects cost nothing.
  const double h = settings.time_step;
  std::vector<WeightedForm> dynamic{{&inertia_, 1.0}}, quasi_static;
  append_if_used(dynamic, &loads_, h * h);
  append_if_used(quasi_static, &loads_, 1.0);
  const auto add_elastic = [&](auto form) {
    append_if_used(quasi_static, form.get(), 1.0);
    static_forms_.push_back(std::move(form));
  };
  add_elastic(make_constraint_form<NeoHookeanKernel>("neo-hookean", model.neo_hookean));
  add_elastic(make_constraint_form<TetVolumeKernel>("tet volume", model.volumes));
  add_elastic(make_constraint_form<DistanceKernel>("distance", model.distances));
  add_elastic(make_constraint_form<AttachmentKernel>("attachment", compliant_attachments_));
  step_neo_hookean_ = make_constraint_form<NeoHookeanKernel>("neo-hookean", model.neo_hookean, h);
  step_volume_ = make_constraint_form<TetVolumeKernel>("tet volume", model.volumes, h);
  step_distance_ = make_constraint_form<DistanceKernel>("distance", model.distances, h);
  step_attachment_ = make_constraint_form<AttachmentKernel>("attachment", compliant_attachments_, h);
  append_if_used(dynamic, step_neo_hookean_.get(), h * h);
  append_if_used(dynamic, step_volume_.get(), h * h);
  append_if_used(dynamic, step_distance_.get(), h * h);
  append_if_used(dynamic, step_attachment_.get(), h * h);
  step_strain_rate_damping_ = std::make_unique<StrainRateDampingForm>(model.neo_hookean, h);
  append_if_used(dynamic, step_strain_rate_damping_.get(), h * h);
  if (model.ground || !model.colliders.empty()) contact_ = std::make_unique<BarrierContactForm>(model, contact);
  const int sphere_bodies = static_cast<int>(std::count_if(model.bodies.begin(), model.bodies.end(), [](const xpbd::Body& b) {
    return b.kind == xpbd::BodyKind::kSoft && b.sphere_count() > 0;
  }));
  if (sphere_bodies >= 2) sphere_pairs_ = std::make_unique<SpherePairContactForm>(model, contact);
  if (sphere_bodies >= 1 && !model.colliders.empty())
    sphere_planes_ = std::make_unique<SpherePlaneContactForm>(model, contact);
  const auto add_contact = [&](auto* form) {
    if (!form) return;
    contact_forms_.push_back(form);
    append_if_used(dynamic, form, h * h);
    append_if_used(quasi_static, form, 1.0);
  };
  add_contact(contact_.get());
  add_contact(sphere_pairs_.get());
  add_contact(sphere_planes_.get());
  dynamic_ = std::make_unique<NewtonSolver>(dynamic, fixed_, settings.newton);
  static_ = std::make_unique<NewtonSolver>(quasi_static, fixed_, settings.newton);
}

ImplicitSolver::~ImplicitSolver() = default;

void ImplicitSolver::hold_rigid_attachments() {
  for (const xpbd::Attachment& a : model_.attachments)
    if (a.compliance == 0.0) model_.particles.x.row(a.particle) = a.target.transpose();
}

void ImplicitSolver::step() {
  const double h = settings_.time_step;
  xpbd::Particles& p = model_.particles;
  hold_rigid_attachments();
  const Positions x_start = p.x;
  Positions x_hat = p.x;
  for (int i = 0; i < p.size(); ++i)
    if (!fixed_[i]) x_hat.row(i) += h * p.v.row(i);
  inertia_.set_target(x_hat);
  step_neo_hookean_->set_targets(x_start);
  step_volume_->set_targets(x_start);
  step_distance_->set_targets(x_start);
  step_strain_rate_damping_->set_start(x_start);

  // Start from XPBD's prediction x̃ = x̂ + h² M⁻¹ f, or as far towards it from xⁿ as the
  // contact barrier allows.
  const bool has_forces = model_.external_forces.rows() != 0;
  p.x = x_hat;
  for (int i = 0; i < p.size(); ++i) {
    if (fixed_[i]) continue;
    xpbd::Vec3 a = model_.gravity;
    if (has_forces) a += p.w[i] * model_.external_forces.row(i).transpose();
    p.x.row(i) += h * h * a.transpose();
  }
  if (!contact_forms_.empty()) {
    require_outside_obstacles(x_start, "step");
    prepare_contact((step_ + 1) * h);
    const Positions towards = p.x - x_start;
    double share = 1.0;
    for (const Form* form : contact_forms_) share = std::min(share, form->max_step(x_start, towards));
    p.x = x_start + share * towards;
  }
  report_ = dynamic_->minimize(p.x);
  check("step");
  p.v = (p.x - x_start) / h;
  for (int i = 0; i < p.size(); ++i)
    if (fixed_[i]) p.v.row(i).setZero();
  ++step_;
}

void ImplicitSolver::prepare_contact(double t) {
  if (contact_) contact_->set_time(t);
  if (sphere_planes_) {
    sphere_planes_->set_time(t);
    sphere_planes_->set_radii(model_);
  }
  if (sphere_pairs_) sphere_pairs_->set_radii(model_);
}

void ImplicitSolver::require_outside_obstacles(const Positions& x, const char* what) const {
  const auto finite = [&](const Form* form) { return std::isfinite(form->value(x)); };
  if (std::all_of(contact_forms_.begin(), contact_forms_.end(), finite)) return;
  throw xpbd::SimulationError("reference solver, " + std::string(what) + " " + std::to_string(step_) +
                              ": a particle or collision sphere is on or inside the ground, a collider or "
                              "another body, where the contact barrier is infinite (start everything apart)");
}

NewtonReport ImplicitSolver::solve_static(const Positions* radii_shape) {
  hold_rigid_attachments();
  if (!contact_forms_.empty()) {
    const Positions start = model_.particles.x;
    if (radii_shape) model_.particles.x = *radii_shape;  // the radii follow model_'s shape
    prepare_contact(step_ * settings_.time_step);
    model_.particles.x = start;
    require_outside_obstacles(model_.particles.x, "static solve");
  }
  report_ = static_->minimize(model_.particles.x);
  check("static solve");
  model_.particles.v.setZero();
  return report_;
}

void ImplicitSolver::check(const char* what) const {
  if (!model_.particles.x.allFinite())
    throw xpbd::SimulationError("reference solver, " + std::string(what) + " " +
                                std::to_string(step_) + ": Newton ended on non-finite positions "
                                "(after " + std::to_string(report_.iterations) + " iterations)");
}

}  // namespace rice::fem
