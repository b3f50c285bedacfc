// XPBD substepping solver; see solver.hpp. Every projection below is one line of XPBD eq. 26
// (damped_update.hpp) around a stateless constraint kernel.
#include "xpbd/solver.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "xpbd/contact_solver.hpp"
#include "xpbd/damped_update.hpp"
#include "xpbd/distance_constraint.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/sleeping.hpp"
#include "xpbd/state_archive.hpp"
#include "xpbd/tet_constraint_pair.hpp"
#include "xpbd/tet_volume_constraint.hpp"
#include "xpbd/vertex_block_descent.hpp"

namespace rice::xpbd {
namespace {

template <size_t Arity, class Constraint>
Coloring color_constraints(const std::vector<Constraint>& constraints, int particle_count) {
  std::vector<int> ids;
  ids.reserve(Arity * constraints.size());
  for (const Constraint& c : constraints) ids.insert(ids.end(), c.particles.begin(), c.particles.end());
  return greedy_coloring(ids, Arity, particle_count);
}

/// The 12 coordinates of a tetrahedron's four particles.
Vec12 tet_stencil(const Positions& x, const std::array<int, 4>& id) {
  return stack(position(x, id[0]), position(x, id[1]), position(x, id[2]), position(x, id[3]));
}

}  // namespace

Solver::Solver(Model& model, const SolverSettings& settings) : model_(model), settings_(settings) {
  const Particles& p = model.particles;
  if (p.v.rows() != p.x.rows() || p.w.size() != p.x.rows())
    throw std::invalid_argument("Solver: particles have " + std::to_string(p.x.rows()) +
                                " positions, " + std::to_string(p.v.rows()) + " velocities, " +
                                std::to_string(p.w.size()) + " inverse masses");
  if (model.external_forces.rows() != 0 && model.external_forces.rows() != p.x.rows())
    throw std::invalid_argument("Solver: external_forces must be empty or one row per particle");
  if (!(settings.time_step > 0.0) || settings.substeps < 1 || settings.iterations < 1)
    throw std::invalid_argument("Solver: need time_step > 0, substeps >= 1, iterations >= 1");
  if (!(settings.pbd_stiffness >= 0.0 && settings.pbd_stiffness <= 1.0))
    throw std::invalid_argument("Solver: pbd_stiffness must lie in [0, 1], got " +
                                std::to_string(settings.pbd_stiffness));
  if (settings.method == Method::kPbd && !model.neo_hookean.empty())
    throw std::invalid_argument(
        "Solver: PBD mode cannot project the Neo-Hookean pair (C_D and C_H are not zero at "
        "rest, so a stiffness in [0, 1] has no meaning for them); use springs and volumes");
  if (settings.method == Method::kVbd && (!model.distances.empty() || !model.volumes.empty()))
    throw std::invalid_argument("Solver: vertex block descent solves Neo-Hookean tets only; this model has "
                                "springs or tet volumes (use Method::kXpbd)");
  const bool strain_rate_damping = std::any_of(model.neo_hookean.begin(), model.neo_hookean.end(),
                                               [](const NeoHookeanTet& t) { return t.strain_rate_damping > 0.0; });
  if (settings.method != Method::kVbd && strain_rate_damping)
    throw std::invalid_argument("Solver: strain-rate damping is solved by vertex block descent only (use "
                                "Method::kVbd); XPBD damps through each constraint's β");
  if (settings.method != Method::kXpbd && settings.primal_correction)
    throw std::invalid_argument("Solver: the primal-residual correction belongs to Method::kXpbd");
  for (const Attachment& a : model.attachments)
    if (a.particle < 0 || a.particle >= p.size())
      throw std::invalid_argument("Solver: attachment names particle " + std::to_string(a.particle));
  if (!model.bodies.empty() || !model.colliders.empty())
    contacts_ = std::make_unique<ContactSolver>(model, settings_.execution == Execution::kParallel);
  coloring_distance_ = color_constraints<2>(model.distances, p.size());
  coloring_volume_ = color_constraints<4>(model.volumes, p.size());
  coloring_neo_hookean_ = color_constraints<4>(model.neo_hookean, p.size());
  tet_blocks_ = body_tet_blocks(model);
  find_awake_runs();
  if (settings.method == Method::kVbd) {
    vbd_ = std::make_unique<VertexBlockDescent>(model);
    if (contacts_) contacts_->hold_in_particle_steps();
  }
}

Solver::~Solver() = default;

namespace {

/// Adds the seconds since `start` to `total` and restarts the clock.
void lap(double& total, std::chrono::steady_clock::time_point& start) {
  const auto now = std::chrono::steady_clock::now();
  total += std::chrono::duration<double>(now - start).count();
  start = now;
}

}  // namespace

void Solver::step() {
  const auto start = std::chrono::steady_clock::now();
  const double h = settings_.time_step / settings_.substeps;
  StepStart step_start;
  if (model_.sleep.enabled) {
    auto clock = std::chrono::steady_clock::now();
    step_start = record_step_start(model_);
    lap(timings_.sleeping, clock);
  }
  const int broad_phase_every =
      std::max(1, static_cast<int>(std::floor(model_.contact.broad_phase_interval / h * (1.0 + 1e-9))));
  bool idle = false;  // the last substep ran with every body asleep and nothing to touch
  for (substep_ = 0; substep_ < settings_.substeps; ++substep_) {
    if (contacts_ && substep_ % broad_phase_every == 0) {
      auto clock = std::chrono::steady_clock::now();
      const int span = std::min(broad_phase_every, settings_.substeps - substep_);
      contacts_->find_candidates(time() + substep_ * h, span * h);
      lap(timings_.broad_phase, clock);
      mark_sleeping();  // the broad phase may wake bodies; a body may also start asleep
      lap(timings_.sleeping, clock);
    }
    // With every body asleep and no body pair in reach, a substep moves nothing; the first
    // clears the contacts' states and the rest repeat it, so they are skipped (a sleeping
    // onigiri took 0.09 s a frame for 480 of them, 2% of its run).
    const bool quiet = contacts_ && all_asleep_ && contacts_->no_candidates();
    if (quiet && idle) continue;
    substep(h, (substep_ + 1) % broad_phase_every == 0 || substep_ + 1 == settings_.substeps);
    idle = quiet;
  }
  if (settings_.diagnostics) diagnostics_ = measure(h);
  if (model_.sleep.enabled) {
    auto clock = std::chrono::steady_clock::now();
    update_sleep(model_, step_start, settings_.time_step);
    lap(timings_.sleeping, clock);
  }
  timings_.total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++step_;
}

void Solver::substep(double h, bool end_of_interval) {
  ++timings_.substeps;
  start_substep_state();
  predict(h);
  if (settings_.diagnostics) x_predicted_ = model_.particles.x;
  // Contacts from the prediction, before vertex block descent's initial guess: the guess may
  // hold a body back where its body steps then carry it to the prediction (started from the
  // guess, a grain 0.1 mm over a plane found no contact and fell through it).
  if (contacts_) {
    auto clock = std::chrono::steady_clock::now();
    contacts_->begin_substep(time() + substep_ * h, h, x_previous_);
    lap(timings_.narrow_phase, clock);
  }
  if (settings_.method == Method::kVbd) start_vertex_block_descent(h);
  for (int k = 0; k < settings_.iterations; ++k) {
    iterate(h);
    if (!contacts_) continue;
    if (vbd_) contacts_->update_particle_contacts();
    contacts_->project(x_previous_);
  }
  Particles& p = model_.particles;
  for (const auto& [first, last] : awake_particles_)
    p.v.middleRows(first, last - first) =
        (p.x.middleRows(first, last - first) - x_previous_.middleRows(first, last - first)) / h;
  for (RigidBody& body : model_.rigid_bodies) update_velocities(body, h);
  if (contacts_) {
    contacts_->end_substep(end_of_interval);
    contacts_->solve_velocities();
  }
  check_positions();
}

void Solver::start_substep_state() {
  const Particles& p = model_.particles;
  if (x_previous_.rows() != p.size()) x_previous_ = p.x;
  for (const auto& [first, last] : awake_particles_)
    x_previous_.middleRows(first, last - first) = p.x.middleRows(first, last - first);
  lambda_distance_.assign(model_.distances.size(), 0.0);
  lambda_volume_.assign(model_.volumes.size(), 0.0);
  lambda_attachment_.assign(model_.attachments.size(), Vec3::Zero());
  // A sleeping tet's multipliers stay zero (mark_sleeping): only the awake ones start afresh.
  using Impulse = Eigen::Matrix<double, 3, 4>;
  lambda_neo_hookean_.resize(model_.neo_hookean.size(), Vec2::Zero());
  if (settings_.primal_correction) impulse_neo_hookean_.resize(model_.neo_hookean.size(), Impulse::Zero());
  for (const auto& [first, last] : awake_tets_) {
    std::fill(lambda_neo_hookean_.begin() + first, lambda_neo_hookean_.begin() + last, Vec2::Zero());
    if (settings_.primal_correction)
      std::fill(impulse_neo_hookean_.begin() + first, impulse_neo_hookean_.begin() + last, Impulse::Zero());
  }
  if (rotation_.size() != model_.neo_hookean.size())
    rotation_.assign(model_.neo_hookean.size(), Eigen::Quaterniond::Identity());
}

void Solver::predict(double h) {
  // x̃ = x + h v + h² M⁻¹ f_ext with f_ext = m g + external forces (pinned particles stay).
  Particles& p = model_.particles;
  const bool has_forces = model_.external_forces.rows() != 0;
  for (const auto& [first, last] : awake_particles_)
    for (int i = first; i < last; ++i) {
      if (p.w[i] == 0.0) {
        p.v.row(i).setZero();
        continue;
      }
      Vec3 acceleration = model_.gravity;
      if (has_forces) acceleration += p.w[i] * model_.external_forces.row(i).transpose();
      p.v.row(i) += h * acceleration.transpose();
      p.x.row(i) += h * p.v.row(i);
    }
  for (size_t r = 0; r < model_.rigid_bodies.size(); ++r) {
    RigidBody& body = model_.rigid_bodies[r];
    if (!asleep_rigid_.empty() && asleep_rigid_[r]) {
      body.remember_pose();
      continue;
    }
    integrate(body, model_.gravity, h);
  }
}

void Solver::start_vertex_block_descent(double h) {
  Particles& p = model_.particles;
  y_ = p.x;
  vbd_->begin_step(model_, x_previous_, h);
  // x⁰ = y − h² a (1 − s), s = clamp(aⁿ·â / |a|, 0, 1), a = g + M⁻¹f_ext the particle's
  // external acceleration and aⁿ = (vⁿ − vⁿ⁻¹)/h; predict() made p.v = vⁿ + h a, so
  // vⁿ = p.v − h a. Before the first substep aⁿ is unknown and s = 0: a body set down at rest
  // at h = 1/60 s would otherwise start 2.7 mm below the ground, flattened on it, and jump (and
  // a grain pressed by a load of five weights 14 mm down, through what holds it).
  const bool has_forces = model_.external_forces.rows() != 0;
  const bool known = v_previous_.rows() == p.size();
  Positions v_start = p.v;
  for (int i = 0; i < p.size(); ++i) {
    if (p.w[i] == 0.0 || (!asleep_particle_.empty() && asleep_particle_[i])) continue;
    Vec3 a = model_.gravity;
    if (has_forces) a += p.w[i] * model_.external_forces.row(i).transpose();
    const double aa = a.squaredNorm();
    if (aa == 0.0) continue;
    v_start.row(i) -= h * a.transpose();
    const double share =
        known ? std::clamp((v_start.row(i) - v_previous_.row(i)).dot(a.transpose()) / (h * aa), 0.0, 1.0) : 0.0;
    p.x.row(i) -= (h * h * (1.0 - share)) * a.transpose();
  }
  // A guess below the ground flattens a body onto it before the sweeps start: keep the guess of
  // a particle that was above the plane on it.
  if (model_.ground) {
    const GroundPlane& ground = *model_.ground;
    for (int i = 0; i < p.size(); ++i) {
      const double depth = ground.offset - ground.normal.dot(p.x.row(i).transpose());
      if (depth > 0.0 && ground.normal.dot(x_previous_.row(i).transpose()) >= ground.offset)
        p.x.row(i) += depth * ground.normal.transpose();
    }
  }
  v_previous_ = std::move(v_start);
}

void Solver::mark_sleeping() {
  asleep_particle_.assign(model_.particles.size(), 0);
  asleep_rigid_.assign(model_.rigid_bodies.size(), 0);
  for (const Body& body : model_.bodies) {
    if (!body.asleep) continue;
    if (body.kind == BodyKind::kRigid)
      asleep_rigid_[body.rigid_body] = 1;
    else
      std::fill_n(asleep_particle_.begin() + body.first_particle, body.particle_count, 1);
  }
  all_asleep_ = true;
  for (int i = 0; i < model_.particles.size() && all_asleep_; ++i)
    all_asleep_ = asleep_particle_[i] || model_.particles.w[i] == 0.0;
  for (size_t r = 0; r < model_.rigid_bodies.size() && all_asleep_; ++r)
    all_asleep_ = asleep_rigid_[r] || model_.rigid_bodies[r].inverse_mass == 0.0;
  // What a substep's start did for every particle and tet, done here for the sleeping ones,
  // which the substeps then skip: xⁿ = x, v = 0 (nothing moves them), multipliers zero.
  Particles& p = model_.particles;
  x_previous_ = p.x;
  for (int i = 0; i < p.size(); ++i)
    if (asleep_particle_[i]) p.v.row(i).setZero();
  lambda_neo_hookean_.assign(model_.neo_hookean.size(), Vec2::Zero());
  if (settings_.primal_correction)
    impulse_neo_hookean_.assign(model_.neo_hookean.size(), Eigen::Matrix<double, 3, 4>::Zero());
  find_awake_runs();
}

std::vector<std::pair<int, int>> Solver::awake_runs(const std::vector<char>& asleep, int count) {
  std::vector<std::pair<int, int>> runs;
  for (int i = 0; i < count; ++i) {
    if (!asleep.empty() && asleep[i]) continue;
    if (runs.empty() || runs.back().second != i) runs.emplace_back(i, i);
    runs.back().second = i + 1;
  }
  return runs;
}

void Solver::find_awake_runs() {
  const int particles = model_.particles.size(), tets = static_cast<int>(model_.neo_hookean.size());
  awake_particles_ = awake_runs(asleep_particle_, particles);
  // A tet sleeps with its body; without body blocks (tets of free particles) every tet is awake.
  std::vector<char> asleep_tet;
  awake_blocks_.clear();
  if (!asleep_particle_.empty()) asleep_tet.assign(tets, 0);
  for (int k = 0; k < static_cast<int>(tet_blocks_.size()); ++k) {
    const TetBlock& block = tet_blocks_[k];
    if (asleep_particle_.empty() || !asleep_particle_[block.first_particle]) awake_blocks_.push_back(k);
    else std::fill(asleep_tet.begin() + block.first, asleep_tet.begin() + block.last, 1);
  }
  if (tet_blocks_.empty()) asleep_tet.clear();
  awake_tets_ = awake_runs(asleep_tet, tets);
}

template <class Project>
void Solver::for_each_constraint(const Coloring& coloring, Project&& project) {
  if (settings_.execution == Execution::kSerial) {
    const int count = static_cast<int>(coloring.order.size());
    for (int c = 0; c < count; ++c) project(c);
    return;
  }
  for (int color = 0; color < coloring.colors(); ++color) {
    const auto members = coloring.color(color);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, members.size(), 128),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t m = range.begin(); m != range.end(); ++m) project(members[m]);
                      });
  }
}

void Solver::iterate(double h) {
  if (settings_.method == Method::kVbd)
    vbd_->sweep(model_, y_, settings_.execution == Execution::kParallel, asleep_particle_,
                contacts_ ? &contacts_->particle_contacts() : nullptr);
  else
    project_neo_hookean_tets(h);
  for_each_constraint(coloring_volume_, [&](int c) { project_volume(c, h); });
  for_each_constraint(coloring_distance_, [&](int c) { project_distance(c, h); });
  project_attachments(h);
  if (model_.ground) project_ground();
}

std::vector<Solver::TetBlock> Solver::body_tet_blocks(const Model& model) {
  const std::vector<int> owner = soft_body_of_particle(model);
  std::vector<char> seen(model.bodies.size(), 0);
  std::vector<TetBlock> blocks;
  for (int c = 0; c < static_cast<int>(model.neo_hookean.size()); ++c) {
    const auto& id = model.neo_hookean[c].particles;
    const int b = owner[id[0]];
    if (b < 0 || owner[id[1]] != b || owner[id[2]] != b || owner[id[3]] != b) return {};  // not one body's
    if (blocks.empty() || owner[model.neo_hookean[blocks.back().first].particles[0]] != b) {
      if (seen[b]) return {};  // the body's tets are not contiguous
      seen[b] = 1;
      blocks.push_back({c, c, model.bodies[b].first_particle});
    }
    blocks.back().last = c + 1;
  }
  return blocks;
}

void Solver::project_neo_hookean_tets(double h) {
  if (h != h_scaled_ || scaled_neo_hookean_.size() != model_.neo_hookean.size()) {
    scaled_neo_hookean_.resize(model_.neo_hookean.size());
    for (size_t c = 0; c < model_.neo_hookean.size(); ++c) {
      const NeoHookeanTet& t = model_.neo_hookean[c];
      scaled_neo_hookean_[c] = {scale_compliance(t.compliance_deviatoric(), t.beta_deviatoric, h),
                                scale_compliance(t.compliance_hydrostatic(), t.beta_hydrostatic, h)};
    }
    h_scaled_ = h;
  }
  if (tet_blocks_.empty() || settings_.execution == Execution::kSerial) {
    for_each_constraint(coloring_neo_hookean_, [&](int c) { project_neo_hookean(c); });
    return;
  }
  // A grain's few dozen tets take microseconds: one parallel loop over the awake bodies per
  // sweep, where colour by colour paid a barrier per colour (30 a sweep) and left threads
  // yielding.
  const tbb::blocked_range<size_t> blocks(0, awake_blocks_.size(), 8);
  tbb::parallel_for(blocks, [&](const tbb::blocked_range<size_t>& range) {
    for (size_t k = range.begin(); k != range.end(); ++k) {
      const TetBlock& block = tet_blocks_[awake_blocks_[k]];
      for (int c = block.first; c < block.last; ++c) project_neo_hookean(c);
    }
  });
}

void Solver::project_distance(int c, double h) {
  const DistanceConstraint& d = model_.distances[c];
  Positions& x = model_.particles.x;
  const Eigen::VectorXd& w = model_.particles.w;
  const int i = d.particles[0], j = d.particles[1];
  const double wi = w[i], wj = w[j];
  if (wi + wj == 0.0) return;
  auto xi = position(x, i);
  auto xj = position(x, j);
  const double C = distance_constraint_value(xi, xj, d.rest_length);
  const Vec6 g = distance_constraint_gradient(xi, xj);
  if (g.isZero()) return;  // coincident particles: no direction to push along
  const Vec3 n = g.head<3>();
  double delta_lambda;
  if (settings_.method == Method::kPbd) {
    delta_lambda = -settings_.pbd_stiffness * C / (wi + wj);
  } else {
    const double grad_dot_dx =
        n.dot((xi - position(x_previous_, i)) - (xj - position(x_previous_, j)));
    delta_lambda = damped_delta_lambda(C, lambda_distance_[c], scale_compliance(d.compliance, d.damping, h),
                                       grad_dot_dx, wi + wj);
    lambda_distance_[c] += delta_lambda;
  }
  if (!std::isfinite(delta_lambda)) fail("distance", c);
  xi += wi * delta_lambda * n;
  xj -= wj * delta_lambda * n;
}

void Solver::project_volume(int c, double h) {
  const TetVolumeConstraint& v = model_.volumes[c];
  Positions& x = model_.particles.x;
  const Eigen::VectorXd& w = model_.particles.w;
  const auto& id = v.particles;
  const Vec12 xs = tet_stencil(x, id);
  const double C = tet_volume_constraint_value(xs, v.rest_volume);
  const Vec12 g = tet_volume_constraint_gradient(xs);
  double grad_w_grad = 0.0, grad_dot_dx = 0.0;
  for (int k = 0; k < 4; ++k) {
    grad_w_grad += w[id[k]] * g.segment<3>(3 * k).squaredNorm();
    grad_dot_dx += g.segment<3>(3 * k).dot(xs.segment<3>(3 * k) - position(x_previous_, id[k]));
  }
  if (grad_w_grad == 0.0) return;
  double delta_lambda;
  if (settings_.method == Method::kPbd) {
    delta_lambda = -settings_.pbd_stiffness * C / grad_w_grad;
  } else {
    delta_lambda = damped_delta_lambda(C, lambda_volume_[c], scale_compliance(v.compliance, v.damping, h),
                                       grad_dot_dx, grad_w_grad);
    lambda_volume_[c] += delta_lambda;
  }
  if (!std::isfinite(delta_lambda)) fail("tet volume", c);
  for (int k = 0; k < 4; ++k) position(x, id[k]) += w[id[k]] * delta_lambda * g.segment<3>(3 * k);
}

void Solver::project_neo_hookean(int c) {
  // The deviatoric and hydrostatic constraints of one tet solved jointly (Macklin & Müller
  // 2021 §5): solved one after the other, the Neo-Hookean pair would fight at rest, where
  // neither is zero.
  const NeoHookeanTet& t = model_.neo_hookean[c];
  if (!asleep_particle_.empty() && asleep_particle_[t.particles[0]]) return;  // a sleeping body's tet
  Positions& x = model_.particles.x;
  const Eigen::VectorXd& w = model_.particles.w;
  const auto& id = t.particles;
  const double wk[4] = {w[id[0]], w[id[1]], w[id[2]], w[id[3]]};
  if (wk[0] + wk[1] + wk[2] + wk[3] == 0.0) return;
  // Gradients for x1..x3 are the columns of (∂C/∂F) Dm⁻ᵀ; x0 gets minus their sum.
  Eigen::Matrix<double, 3, 4> grad_D, grad_H;
  const auto pair = [&] {
    const Mat3 F = edge_matrix(position(x, id[0]), position(x, id[1]), position(x, id[2]), position(x, id[3])) *
                   t.Dm_inv;
    Mat3 R = Mat3::Identity();
    if (t.corotated()) {
      refine_polar_rotation(F, rotation_[c]);
      R = rotation_[c].toRotationMatrix();
    }
    const TetConstraintPair p = tet_constraint_pair(t, F, R);
    grad_D.rightCols<3>() = p.dD * t.Dm_inv.transpose();
    grad_H.rightCols<3>() = p.dH * t.Dm_inv.transpose();
    grad_D.col(0) = -grad_D.rightCols<3>().rowwise().sum();
    grad_H.col(0) = -grad_H.rightCols<3>().rowwise().sum();
    return p.C;
  };
  const bool correct = settings_.primal_correction && settings_.method == Method::kXpbd;
  if (correct) {
    // Re-apply the accumulated λ along the current gradients (see SolverSettings).
    pair();
    const Vec2& lambda = lambda_neo_hookean_[c];
    const Eigen::Matrix<double, 3, 4> impulse = grad_D * lambda[0] + grad_H * lambda[1];
    for (int k = 0; k < 4; ++k)
      position(x, id[k]) += wk[k] * (impulse.col(k) - impulse_neo_hookean_[c].col(k));
    impulse_neo_hookean_[c] = impulse;
  }
  const Vec2 C = pair();
  Mat2 gwg = Mat2::Zero();
  Vec2 grad_dot_dx = Vec2::Zero();
  for (int k = 0; k < 4; ++k) {
    gwg(0, 0) += wk[k] * grad_D.col(k).squaredNorm();
    gwg(0, 1) += wk[k] * grad_D.col(k).dot(grad_H.col(k));
    gwg(1, 1) += wk[k] * grad_H.col(k).squaredNorm();
    const Vec3 dx = position(x, id[k]) - position(x_previous_, id[k]);
    grad_dot_dx[0] += grad_D.col(k).dot(dx);
    grad_dot_dx[1] += grad_H.col(k).dot(dx);
  }
  gwg(1, 0) = gwg(0, 1);
  const auto& [scaled_D, scaled_H] = scaled_neo_hookean_[c];
  const Vec2 delta_lambda = damped_delta_lambda_pair(C, lambda_neo_hookean_[c], scaled_D, scaled_H, grad_dot_dx, gwg);
  if (!delta_lambda.allFinite()) fail("neo-hookean tet", c);
  lambda_neo_hookean_[c] += delta_lambda;
  for (int k = 0; k < 4; ++k)
    position(x, id[k]) += wk[k] * (grad_D.col(k) * delta_lambda[0] + grad_H.col(k) * delta_lambda[1]);
  if (correct) impulse_neo_hookean_[c] += grad_D * delta_lambda[0] + grad_H * delta_lambda[1];
}

void Solver::project_attachments(double h) {
  // C = x − p: three constraints with gradient I, solved together in closed form.
  Positions& x = model_.particles.x;
  for (size_t a = 0; a < model_.attachments.size(); ++a) {
    const Attachment& attachment = model_.attachments[a];
    if (vbd_ && attachment.compliance > 0.0) continue;  // a spring of the particles' steps
    const double w = model_.particles.w[attachment.particle];
    const double alpha_tilde = attachment.compliance / (h * h);
    if (w + alpha_tilde == 0.0) continue;
    auto xi = position(x, attachment.particle);
    const Vec3 delta_lambda = (-(xi - attachment.target) - alpha_tilde * lambda_attachment_[a]) /
                              (w + alpha_tilde);
    if (!delta_lambda.allFinite()) fail("attachment", static_cast<int>(a));
    lambda_attachment_[a] += delta_lambda;
    xi += w * delta_lambda;
  }
}

void Solver::project_ground() {
  // C = n·x − d ≥ 0 with α = 0: a particle below the plane moves back onto it along n; then
  // friction removes (static) or shortens (dynamic) its tangential motion over the substep in
  // proportion to the penetration depth (Macklin et al. 2014, eq. 24).
  const GroundPlane& ground = *model_.ground;
  Particles& p = model_.particles;
  for (int i = 0; i < p.size(); ++i) {
    if (p.w[i] == 0.0) continue;
    auto xi = position(p.x, i);
    const double depth = ground.offset - ground.normal.dot(xi);
    if (depth <= 0.0) continue;
    xi += depth * ground.normal;
    const Vec3 dx = xi - position(x_previous_, i);
    const Vec3 tangential = dx - ground.normal.dot(dx) * ground.normal;
    const double slip = tangential.norm();
    if (slip < ground.static_friction * depth)
      xi -= tangential;
    else if (slip > 0.0)
      xi -= tangential * std::min(ground.dynamic_friction * depth / slip, 1.0);
  }
}

void Solver::check_positions() const {
  const Positions& x = model_.particles.x;
  for (const auto& [first, last] : awake_particles_)  // a sleeping particle has not moved
    for (int i = first; i < last; ++i)
      if (!x.row(i).allFinite())
        throw SimulationError("step " + std::to_string(step_) + ", substep " + std::to_string(substep_) +
                              ": particle " + std::to_string(i) +
                              " has a non-finite position (check its velocity, mass and forces)");
  const auto& rigid = model_.rigid_bodies;
  for (size_t b = 0; b < rigid.size(); ++b)
    if (!rigid[b].x.allFinite() || !rigid[b].q().coeffs().allFinite())
      throw SimulationError("step " + std::to_string(step_) + ", substep " + std::to_string(substep_) +
                            ": rigid body " + std::to_string(b) + " has a non-finite pose");
}

void Solver::fail(const char* constraint_type, int index) const {
  throw SimulationError("step " + std::to_string(step_) + ", substep " + std::to_string(substep_) +
                        ": non-finite multiplier update in " + constraint_type + " constraint " +
                        std::to_string(index));
}

Positions Solver::constraint_impulses() const {
  const Positions& x = model_.particles.x;
  Positions impulse = Positions::Zero(x.rows(), 3);
  const auto add = [&](const auto& ids, const auto& gradient, double lambda) {
    for (size_t k = 0; k < ids.size(); ++k)
      impulse.row(ids[k]) += lambda * gradient.template segment<3>(3 * k).transpose();
  };
  for (size_t c = 0; c < model_.distances.size(); ++c) {
    const DistanceConstraint& d = model_.distances[c];
    add(d.particles, distance_constraint_gradient(position(x, d.particles[0]), position(x, d.particles[1])),
        lambda_distance_[c]);
  }
  for (size_t c = 0; c < model_.volumes.size(); ++c)
    add(model_.volumes[c].particles, tet_volume_constraint_gradient(tet_stencil(x, model_.volumes[c].particles)),
        lambda_volume_[c]);
  for (size_t c = 0; c < model_.neo_hookean.size(); ++c) {
    const NeoHookeanTet& t = model_.neo_hookean[c];
    const TetConstraintPair p = tet_constraint_pair(t, deformation_gradient(tet_stencil(x, t.particles), t.Dm_inv));
    const Vec2& lambda = lambda_neo_hookean_[c];
    add(t.particles, gradient_from_dF(Mat3(p.dD * lambda[0] + p.dH * lambda[1]), t.Dm_inv), 1.0);
  }
  for (size_t a = 0; a < model_.attachments.size(); ++a)
    impulse.row(model_.attachments[a].particle) += lambda_attachment_[a].transpose();
  return impulse;
}

StepDiagnostics Solver::measure(double h) const {
  // Residuals of the last substep: h_c = C + α̃λ + γ∇C(x − xⁿ) per constraint, and
  // g = M(x − x̃) − Σ ∇Cᵀλ per particle.
  const Positions& x = model_.particles.x;
  const Eigen::VectorXd& w = model_.particles.w;
  double residual2 = 0.0;
  const auto add = [&](double C, double alpha, double beta, double lambda, double grad_dot_dx) {
    const ScaledCompliance s = scale_compliance(alpha, beta, h);
    const double r = C + s.alpha_tilde * lambda + s.gamma * grad_dot_dx;
    residual2 += r * r;
  };
  const auto displacement = [&](int i) -> Vec3 { return position(x, i) - position(x_previous_, i); };
  const auto stencil_displacement = [&](const auto& ids) {
    Vec12 dx;
    for (int k = 0; k < 4; ++k) dx.segment<3>(3 * k) = displacement(ids[k]);
    return dx;
  };
  for (size_t c = 0; c < model_.distances.size(); ++c) {
    const DistanceConstraint& d = model_.distances[c];
    const Vec3 xi = position(x, d.particles[0]), xj = position(x, d.particles[1]);
    Vec6 dx;
    dx << displacement(d.particles[0]), displacement(d.particles[1]);
    add(distance_constraint_value(xi, xj, d.rest_length), d.compliance, d.damping, lambda_distance_[c],
        distance_constraint_gradient(xi, xj).dot(dx));
  }
  for (size_t c = 0; c < model_.volumes.size(); ++c) {
    const TetVolumeConstraint& v = model_.volumes[c];
    const auto& id = v.particles;
    const Vec12 xs = tet_stencil(x, id);
    add(tet_volume_constraint_value(xs, v.rest_volume), v.compliance, v.damping, lambda_volume_[c],
        tet_volume_constraint_gradient(xs).dot(stencil_displacement(id)));
  }
  for (size_t c = 0; c < model_.neo_hookean.size(); ++c) {
    const NeoHookeanTet& t = model_.neo_hookean[c];
    const auto& id = t.particles;
    const TetConstraintPair p = tet_constraint_pair(t, deformation_gradient(tet_stencil(x, id), t.Dm_inv));
    const Vec12 dx = stencil_displacement(id);
    const Vec2& lambda = lambda_neo_hookean_[c];
    add(p.C[0], t.compliance_deviatoric(), t.beta_deviatoric, lambda[0], gradient_from_dF(p.dD, t.Dm_inv).dot(dx));
    add(p.C[1], t.compliance_hydrostatic(), t.beta_hydrostatic, lambda[1], gradient_from_dF(p.dH, t.Dm_inv).dot(dx));
  }
  for (size_t a = 0; a < model_.attachments.size(); ++a) {
    const Attachment& attachment = model_.attachments[a];
    const Vec3 r = (position(x, attachment.particle) - attachment.target) +
                   attachment.compliance / (h * h) * lambda_attachment_[a];
    residual2 += r.squaredNorm();
  }
  const Positions impulse = constraint_impulses();
  StepDiagnostics d;
  d.step = step_;
  d.constraint_residual = std::sqrt(residual2);
  for (int i = 0; i < x.rows(); ++i)
    if (w[i] > 0.0) d.primal_residual += ((x.row(i) - x_predicted_.row(i)) / w[i] - impulse.row(i)).squaredNorm();
  d.primal_residual = std::sqrt(d.primal_residual);
  d.kinetic_energy = kinetic_energy(model_);
  d.gravitational_energy = gravitational_energy(model_);
  d.elastic_energy = elastic_energy(model_);
  d.max_speed = max_speed(model_.particles);
  return d;
}

/// The model's particles and rigid bodies and its bodies' sleep, then the solver's own: the
/// corotated tets' rotations and vertex block descent's last velocities (both warm starts),
/// the step count and timings, and the contact solver's. The multipliers and the substep's
/// positions start afresh each substep, and the sleep marks are rebuilt from the bodies at each
/// step's first broad phase (mark_sleeping), so none of them is kept.
template <class Self, class Archive>
void Solver::transfer_state(Self& self, Archive& archive) {
  auto& model = self.model_;
  const long particles = model.particles.size(), rigid = static_cast<long>(model.rigid_bodies.size());
  archive(model.particles.x, model.particles.v, model.rigid_bodies);
  if (model.particles.size() != particles || static_cast<long>(model.rigid_bodies.size()) != rigid)
    throw std::runtime_error("the state's particles or rigid bodies do not match the model's");
  for (auto& body : model.bodies) archive(body.asleep, body.quiet_steps, body.moving);
  archive(self.rotation_, self.v_previous_, self.step_, self.timings_);
  bool contacts = self.contacts_ != nullptr;
  archive(contacts);
  if (contacts != (self.contacts_ != nullptr)) throw std::runtime_error("the state's contacts do not match the model's");
  if (self.contacts_) {
    if constexpr (std::is_const_v<Self>) self.contacts_->save_state(archive);
    else self.contacts_->load_state(archive);
  }
}

void Solver::save_state(StateWriter& out) const { transfer_state(*this, out); }
void Solver::load_state(StateReader& in) { transfer_state(*this, in); }

}  // namespace rice::xpbd
