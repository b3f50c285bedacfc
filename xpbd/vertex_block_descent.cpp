// Gauss–Seidel over particles on the step's potential; see vertex_block_descent.hpp.
#include "xpbd/vertex_block_descent.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "xpbd/strain_rate_damping.hpp"
#include "xpbd/tet_constraint_pair.hpp"

namespace rice::xpbd {
namespace {

Mat3 deformation(const Positions& x, const NeoHookeanTet& t) {
  const auto& id = t.particles;
  return edge_matrix(position(x, id[0]), position(x, id[1]), position(x, id[2]), position(x, id[3])) * t.Dm_inv;
}

Vec2 constraint_values(const NeoHookeanTet& t, const Mat3& F) { return tet_constraint_pair(t, F).C; }

/// The deviatoric term's vertex Hessian, (k_D + b_D) g gᵀ + f_D ∂²C_D/∂x_i², for the particle
/// with stencil weights b, g = ∂C_D/∂x_i and f_D = k_D C_D + b_D Ċ_D h. Corotated: Gauss–Newton,
/// k_D ‖b‖² I + b_D g gᵀ: the Hessian of ½ k_D ‖F − R‖² without −k_D ∂R/∂F (negative
/// semi-definite, so dropping it keeps the system positive definite) and of the damping
/// without its f-term, whose ∂²C_D/∂x² grows as 1/C_D near rest.
Mat3 deviatoric_vertex_hessian(const NeoHookeanTet& t, const Mat3& F, const Vec3& b, const Vec3& g, double k,
                               double damping, double force) {
  if (t.corotated()) return k * b.squaredNorm() * Mat3::Identity() + damping * g * g.transpose();
  return (k + damping) * g * g.transpose() + force * neo_hookean_deviatoric_vertex_hessian(F, b);
}

/// Greedy colouring of the particles that have corners: each, in index order, takes the
/// smallest colour no particle of its tets has yet.
Coloring color_particles(const Model& model, const std::vector<int>& first, const auto& corners) {
  const int n = model.particles.size();
  std::vector<int> color(n, -1);
  std::vector<char> taken;
  int colors = 0;
  for (int i = 0; i < n; ++i) {
    if (first[i] == first[i + 1]) continue;
    taken.assign(colors + 1, 0);
    for (int c = first[i]; c < first[i + 1]; ++c)
      for (const int j : model.neo_hookean[corners[c].tet].particles)
        if (color[j] >= 0) taken[color[j]] = 1;
    color[i] = static_cast<int>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    colors = std::max(colors, color[i] + 1);
  }
  return group_by_color(color);
}

}  // namespace

VertexBlockDescent::VertexBlockDescent(const Model& model) {
  const int n = model.particles.size();
  first_corner_.assign(n + 1, 0);
  for (const NeoHookeanTet& t : model.neo_hookean)
    for (const int i : t.particles) ++first_corner_[i + 1];
  for (int i = 0; i < n; ++i) first_corner_[i + 1] += first_corner_[i];
  corners_.resize(first_corner_.back());
  std::vector<int> next(first_corner_.begin(), first_corner_.end() - 1);
  for (size_t e = 0; e < model.neo_hookean.size(); ++e) {
    const NeoHookeanTet& t = model.neo_hookean[e];
    constraint_damping_ = constraint_damping_ || t.beta_deviatoric > 0.0 || t.beta_hydrostatic > 0.0;
    strain_rate_damping_ = strain_rate_damping_ || t.strain_rate_damping > 0.0;
    for (int k = 0; k < 4; ++k) corners_[next[t.particles[k]]++] = {static_cast<int>(e), k};
  }
  coloring_ = color_particles(model, first_corner_, corners_);
  for (size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].kind == BodyKind::kSoft) soft_bodies_.push_back(static_cast<int>(b));
  first_spring_.assign(n + 1, 0);
  for (const Attachment& a : model.attachments)
    if (a.compliance > 0.0) ++first_spring_[a.particle + 1];
  for (int i = 0; i < n; ++i) first_spring_[i + 1] += first_spring_[i];
  springs_.resize(first_spring_.back());
  std::vector<int> slot(first_spring_.begin(), first_spring_.end() - 1);
  for (size_t a = 0; a < model.attachments.size(); ++a)
    if (model.attachments[a].compliance > 0.0) springs_[slot[model.attachments[a].particle]++] = static_cast<int>(a);
}

void VertexBlockDescent::begin_step(const Model& model, const Positions& x_start, double h) {
  h_ = h;
  x_start_ = &x_start;
  const size_t count = model.neo_hookean.size();
  if (constraint_damping_) C_start_.resize(count);
  if (strain_rate_damping_) F_start_.resize(count);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 256), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t e = range.begin(); e != range.end(); ++e) {
      const NeoHookeanTet& t = model.neo_hookean[e];
      const Mat3 F = deformation(x_start, t);
      if (constraint_damping_) C_start_[e] = constraint_values(t, F);
      if (strain_rate_damping_) F_start_[e] = F;
    }
  });
}

void VertexBlockDescent::sweep(Model& model, const Positions& y, bool parallel, const std::vector<char>& frozen,
                               const ParticleContacts* contacts) const {
  if (contacts && contacts->empty()) contacts = nullptr;
  const auto visit = [&](int i) {
    if (model.particles.w[i] == 0.0 || (!frozen.empty() && frozen[i])) return;
    solve_particle(model, y, i, contacts);
  };
  const auto in_contact = [&](int i) { return contacts && contacts->touches(i); };
  for (int color = 0; color < coloring_.colors(); ++color) {
    const auto members = coloring_.color(color);
    if (!parallel) {
      for (const int i : members) visit(i);
      continue;
    }
    tbb::parallel_for(tbb::blocked_range<size_t>(0, members.size(), 64), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t m = range.begin(); m != range.end(); ++m)
        if (!in_contact(members[m])) visit(members[m]);
    });
    for (const int i : members)
      if (in_contact(i)) visit(i);
  }
  // Then each soft body as a whole: the particles' steps leave its translation (see the header).
  if (model.ground) return;
  for (const int b : soft_bodies_) {
    const Body& body = model.bodies[b];
    if (body.asleep || (!frozen.empty() && frozen[body.first_particle])) continue;
    body_step(model, y, b, contacts);
  }
}

double VertexBlockDescent::particle_energy(const Model& model, const Positions& y, int i, const Vec3& xi,
                                           const ParticleContacts* contacts) const {
  const Positions& x = model.particles.x;
  const Vec3 offset = xi - position(x, i);
  double energy = 0.5 / (model.particles.w[i] * h_ * h_) * (xi - position(y, i)).squaredNorm();
  if (contacts) energy += contacts->particle_energy(x, i, offset);
  for (int s = first_spring_[i]; s < first_spring_[i + 1]; ++s) {
    const Attachment& a = model.attachments[springs_[s]];
    energy += 0.5 / a.compliance * (xi - a.target).squaredNorm();
  }
  for (int c = first_corner_[i]; c < first_corner_[i + 1]; ++c) {
    const NeoHookeanTet& t = model.neo_hookean[corners_[c].tet];
    const Mat3 F = deformation(x, t) + offset * stencil_weights(t.Dm_inv, corners_[c].k).transpose();
    const Vec2 C = constraint_values(t, F);
    energy += 0.5 * (C[0] * C[0] / t.compliance_deviatoric() + C[1] * C[1] / t.compliance_hydrostatic());
    if (constraint_damping_) {
      const Vec2 rate = C - C_start_[corners_[c].tet];
      energy += 0.5 / h_ * (t.beta_deviatoric * rate[0] * rate[0] + t.beta_hydrostatic * rate[1] * rate[1]);
    }
    if (t.strain_rate_damping > 0.0) {
      const Mat3& F_start = F_start_[corners_[c].tet];
      energy += t.strain_rate_damping * t.rest_volume / h_ *
                strain_rate_damping_value(F_start, F - F_start, t.mu, t.lambda_lame());
    }
  }
  return energy;
}

void VertexBlockDescent::body_step(Model& model, const Positions& y, int b, const ParticleContacts* contacts) const {
  const Body& body = model.bodies[b];
  Positions& x = model.particles.x;
  const Eigen::VectorXd& w = model.particles.w;
  const int first = body.first_particle, last = body.first_particle + body.particle_count;
  Vec3 gradient = Vec3::Zero();
  Mat3 hessian = Mat3::Zero();
  for (int i = first; i < last; ++i) {
    if (w[i] == 0.0) return;  // pinned: the body cannot translate
    const double inertia = 1.0 / (w[i] * h_ * h_);
    gradient += inertia * (position(x, i) - position(y, i));
    hessian.diagonal().array() += inertia;
    for (int s = first_spring_[i]; s < first_spring_[i + 1]; ++s) {
      const Attachment& a = model.attachments[springs_[s]];
      gradient += (position(x, i) - a.target) / a.compliance;
      hessian.diagonal().array() += 1.0 / a.compliance;
    }
  }
  if (contacts) contacts->add_body_terms(x, b, gradient, hessian);
  // E of the body's translation by δ, up to a constant (its tets' terms do not change).
  const auto energy = [&](const Vec3& shift) {
    double e = contacts ? contacts->body_energy(x, b, shift) : 0.0;
    for (int i = first; i < last; ++i) {
      e += 0.5 / (w[i] * h_ * h_) * (position(x, i) + shift - position(y, i)).squaredNorm();
      for (int s = first_spring_[i]; s < first_spring_[i + 1]; ++s) {
        const Attachment& a = model.attachments[springs_[s]];
        e += 0.5 / a.compliance * (position(x, i) + shift - a.target).squaredNorm();
      }
    }
    return e;
  };
  Vec3 step = -hessian.llt().solve(gradient);
  if (!step.allFinite()) return;
  const double start = energy(Vec3::Zero());
  for (int halvings = 0; energy(step) > start; ++halvings) {
    if (halvings == 8) return;
    step *= 0.5;
  }
  for (int i = first; i < last; ++i) position(x, i) += step;
}

void VertexBlockDescent::solve_particle(Model& model, const Positions& y, int i,
                                        const ParticleContacts* contacts) const {
  Positions& x = model.particles.x;
  const double inertia = 1.0 / (model.particles.w[i] * h_ * h_);  // m_i / h²
  Vec3 gradient = inertia * (position(x, i) - position(y, i));
  Mat3 hessian = Mat3::Zero();  // of the tets' terms; the inertia is added below
  for (int c = first_corner_[i]; c < first_corner_[i + 1]; ++c) {
    const NeoHookeanTet& t = model.neo_hookean[corners_[c].tet];
    const Vec3 b = stencil_weights(t.Dm_inv, corners_[c].k);
    const Mat3 F = deformation(x, t);
    // U + Ψ^C through the constraint kernels: ∂/∂C_r = k_r C_r + b_r (C_r − C_r(xⁿ)),
    // ∂²/∂C_r² = k_r + b_r with k = 1/α, b = β/h (fem_reference/constraint_potential_form.hpp).
    const TetConstraintPair p = tet_constraint_pair(t, F);
    const Vec2 k(1.0 / t.compliance_deviatoric(), 1.0 / t.compliance_hydrostatic());
    const Vec2 damping = constraint_damping_ ? Vec2(t.beta_deviatoric / h_, t.beta_hydrostatic / h_) : Vec2::Zero();
    const Vec2 rate = constraint_damping_ ? Vec2(p.C - C_start_[corners_[c].tet]) : Vec2::Zero();
    const Vec2 force = k.cwiseProduct(p.C) + damping.cwiseProduct(rate);
    const Vec3 gD = vertex_gradient(p.dD, b);
    const Vec3 gH = vertex_gradient(p.dH, b);
    gradient += force[0] * gD + force[1] * gH;
    // ∂²C_H/∂x_i² = 0: det(F + δbᵀ) is linear in δ (the matrix determinant lemma).
    hessian += deviatoric_vertex_hessian(t, F, b, gD, k[0], damping[0], force[0]) +
               (k[1] + damping[1]) * gH * gH.transpose();
    if (t.strain_rate_damping > 0.0) {
      const Mat3& F_start = F_start_[corners_[c].tet];
      const double scale = t.strain_rate_damping * t.rest_volume / h_;  // τV/h of Ψ^E
      gradient += scale * vertex_gradient(strain_rate_damping_dF(F_start, F - F_start, t.mu, t.lambda_lame()), b);
      hessian += scale * strain_rate_damping_vertex_hessian(F_start, b, t.mu, t.lambda_lame());
    }
  }
  if (contacts) contacts->add_particle_terms(x, i, gradient, hessian);
  for (int s = first_spring_[i]; s < first_spring_[i + 1]; ++s) {
    const Attachment& a = model.attachments[springs_[s]];
    gradient += (position(x, i) - a.target) / a.compliance;
    hessian += Mat3::Identity() / a.compliance;
  }
  Mat3 system = hessian + inertia * Mat3::Identity();
  Eigen::LLT<Mat3> newton(system);
  if (newton.info() != Eigen::Success) {
    Eigen::SelfAdjointEigenSolver<Mat3> eigen;
    eigen.computeDirect(hessian);
    system = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose() +
             inertia * Mat3::Identity();
    newton.compute(system);
  }
  const Vec3 xi = position(x, i);
  Vec3 step = -newton.solve(gradient);
  if (model.ground && model.ground->normal.dot(xi + step) < model.ground->offset) {
    position(x, i) += ground_contact_step(*model.ground, xi, position(*x_start_, i), system, newton, gradient);
    return;
  }
  // In one particle's coordinates E is a convex quadratic (‖F‖² is, det F is affine in them,
  // the strain-rate damping is quadratic), so the Newton step is its minimiser; only the
  // constraints' Rayleigh term (C_D − C_D(xⁿ))², not convex where C_D < C_D(xⁿ), can make the
  // step raise E. Then halve it until it does not; after eight halvings, stay.
  if (!constraint_damping_) {
    position(x, i) += step;
    return;
  }
  const double energy = particle_energy(model, y, i, xi, contacts);
  int halvings = 0;
  while (particle_energy(model, y, i, xi + step, contacts) > energy) {
    step *= 0.5;
    if (++halvings == 8) return;
  }
  position(x, i) += step;
}

Vec3 VertexBlockDescent::ground_contact_step(const GroundPlane& ground, const Vec3& x, const Vec3& x_start,
                                             const Mat3& H, const Eigen::LLT<Mat3>& newton, const Vec3& g) {
  const Vec3& n = ground.normal;
  const Vec3 Hinv_n = newton.solve(n);
  // The minimiser of q − Fᵀ Δ on the plane, F a tangential force: Δ = Δ_free + ν H⁻¹n with
  // ν = depth / (nᵀH⁻¹n) the normal force that holds it there.
  const auto on_plane = [&](const Vec3& force, double& normal_force) {
    const Vec3 free_step = -newton.solve(g - force);
    normal_force = std::max(ground.offset - n.dot(x + free_step), 0.0) / n.dot(Hinv_n);
    return Vec3(free_step + normal_force * Hinv_n);
  };
  double normal = 0.0;
  const Vec3 frictionless = on_plane(Vec3::Zero(), normal);
  // Sticking: back where it was at the step's start, on the plane. The tangential force that
  // needs (the minimiser of q(Δ) − fᵀΔ has HΔ + g = f) must lie in the cone μ_s f_n.
  const Vec3 stick = x_start - (n.dot(x_start) - ground.offset) * n - x;
  const Vec3 holding = H * stick + g;
  const Vec3 tangential = holding - n.dot(holding) * n;
  const double tangential_norm = tangential.norm();
  if (tangential_norm <= ground.static_friction * normal) return stick;
  if (tangential_norm == 0.0 || ground.dynamic_friction == 0.0) return frictionless;
  // Sliding: kinetic friction μ_k f_n along the holding force.
  double unused = 0.0;
  return on_plane(ground.dynamic_friction * normal / tangential_norm * tangential, unused);
}

}  // namespace rice::xpbd
