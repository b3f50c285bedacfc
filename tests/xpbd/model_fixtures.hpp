// Small models shared by the solver tests: an elastic block, a cantilever, a spring chain.
#pragma once

#include <Eigen/Geometry>

#include "xpbd/model.hpp"

namespace rice::xpbd::test_support {

/// A Neo-Hookean block [0, size]³ of n³ cubes (6 tets each), gravity off unless asked.
inline Model neo_hookean_block(double size, int n, double young = 1e5, double poisson = 0.3,
                               double rayleigh_time = 0.0, double density = 1000.0) {
  const TetMesh mesh = make_box_tet_mesh(Vec3::Constant(size), n, n, n);
  Model model;
  model.particles = make_particles(mesh, density);
  add_neo_hookean_tets(model, mesh, lame_from_young_poisson(young, poisson), rayleigh_time);
  model.gravity.setZero();
  return model;
}

/// A cantilever of length 1 m and section 0.1 m × 0.1 m along x, clamped at x = 0, under
/// gravity, Neo-Hookean. Returns the model; `tip` receives a vertex on the free end's axis.
inline Model neo_hookean_cantilever(int nx, double young, double rayleigh_time, int* tip = nullptr) {
  const int n = 2;
  const TetMesh mesh = make_box_tet_mesh(Vec3(1.0, 0.1, 0.1), nx, n, n);
  Model model;
  model.particles = make_particles(mesh, 1000.0);
  add_neo_hookean_tets(model, mesh, lame_from_young_poisson(young, 0.3), rayleigh_time);
  pin_particles(model, vertices_at_min_x(mesh.V));
  if (tip) *tip = box_vertex_index(nx, n, nx, 1, 1);
  return model;
}

/// A horizontal chain of `n` particles 0.1 m apart joined by distance constraints of
/// compliance α, pinned at particle 0, under gravity; the last particle is `heavy`× heavier.
inline Model spring_chain(int n, double compliance, double heavy) {
  Model model;
  model.particles.x = Positions::Zero(n, 3);
  for (int i = 0; i < n; ++i) model.particles.x(i, 0) = 0.1 * i;
  model.particles.v = Positions::Zero(n, 3);
  model.particles.w = Eigen::VectorXd::Ones(n);
  model.particles.w[n - 1] = 1.0 / heavy;
  for (int i = 0; i + 1 < n; ++i) model.distances.push_back({{i, i + 1}, 0.1, compliance, 0.0});
  pin_particles(model, {0});
  return model;
}

/// Rotates every particle of the model about the origin.
inline void rotate(Model& model, const Mat3& R) {
  model.particles.x = (model.particles.x * R.transpose()).eval();
}

}  // namespace rice::xpbd::test_support
