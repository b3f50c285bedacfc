// A quasi-static cantilever in the reference solver against beam theory (issue 3, §2): tip
// deflection under a tip load and under gravity at small deflection (δ/L < 1e-3) compared
// with Euler–Bernoulli plus Timoshenko's shear term (Cowper's κ), over four mesh levels.
// Linear tets lock in bending, so the coarse levels are far too stiff; the test states the
// error at every level, requires it to shrink with each refinement, and bounds the finest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fem_reference/implicit_solver.hpp"

namespace rice::fem {
namespace {

using xpbd::Vec3;

struct Beam {
  double length = 0.1, side = 0.02;  // square section [m]
  double young = 1e8, poisson = 0.3, density = 1000.0;
  double tip_load = 0.01;  // [N], downwards
  double area() const { return side * side; }
  double second_moment() const { return side * side * side * side / 12.0; }
  double shear_modulus() const { return young / (2.0 * (1.0 + poisson)); }
  double shear_coefficient() const { return 10.0 * (1.0 + poisson) / (12.0 + 11.0 * poisson); }
};

enum class Load { kTip, kGravity };

/// δ_EB + δ_shear: P L³/(3EI) + P L/(κGA), or q L⁴/(8EI) + q L²/(2κGA) with q = ρ g A.
double analytic_deflection(const Beam& b, Load load) {
  const double EI = b.young * b.second_moment(), kGA = b.shear_coefficient() * b.shear_modulus() * b.area();
  const double L = b.length;
  if (load == Load::kTip) return b.tip_load * L * L * L / (3.0 * EI) + b.tip_load * L / kGA;
  const double q = b.density * 9.81 * b.area();
  return q * L * L * L * L / (8.0 * EI) + q * L * L / (2.0 * kGA);
}

/// Mean downward displacement of the tip face, mesh nx × n × n, clamped at x = 0.
double simulated_deflection(const Beam& b, Load load, int nx, int n) {
  const xpbd::TetMesh mesh = xpbd::make_box_tet_mesh(Vec3(b.length, b.side, b.side), nx, n, n);
  xpbd::Model model;
  model.particles = xpbd::make_particles(mesh, b.density);
  xpbd::add_neo_hookean_tets(model, mesh, xpbd::lame_from_young_poisson(b.young, b.poisson));
  xpbd::pin_particles(model, xpbd::vertices_at_min_x(mesh.V));
  std::vector<int> tip;
  for (int j = 0; j <= n; ++j)
    for (int k = 0; k <= n; ++k) tip.push_back(xpbd::box_vertex_index(nx, n, nx, j, k));
  if (load == Load::kTip) {
    model.gravity.setZero();
    model.external_forces = Positions::Zero(mesh.V.rows(), 3);
    // Consistent nodal loads of a uniform traction on the tip face (bilinear weights).
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const double w = (j == 0 || j == n ? 0.5 : 1.0) * (k == 0 || k == n ? 0.5 : 1.0) / (n * n);
        model.external_forces(xpbd::box_vertex_index(nx, n, nx, j, k), 2) = -b.tip_load * w;
      }
  }
  ImplicitSolver solver(model, {.newton = {.tolerance = 1e-10}});
  const NewtonReport report = solver.solve_static();
  EXPECT_TRUE(report.converged) << "level " << nx << "x" << n << "x" << n;
  double sum = 0.0;
  for (int v : tip) sum += mesh.V(v, 2) - model.particles.x(v, 2);
  return sum / tip.size();
}

/// Errors at four levels must fall with every refinement, at order ≥ 1 between the last two
/// levels (measured 1.5: locking fades), and be under `finest_bound` at the finest.
void check_mesh_convergence(Load load, const char* name, double finest_bound) {
  const Beam beam;
  const double exact = analytic_deflection(beam, load);
  ASSERT_LT(exact / beam.length, 1e-3) << "small-deflection regime";
  std::printf("cantilever, %s: analytic tip deflection %.6e m\n", name, exact);
  std::printf("%10s %8s %14s %12s %8s\n", "mesh", "tets", "deflection [m]", "rel. error", "order");
  double previous_error = 0.0, order = 0.0;
  for (const int n : {1, 2, 4, 8}) {
    const int nx = 5 * n;
    const double deflection = simulated_deflection(beam, load, nx, n);
    const double error = std::abs(deflection - exact) / exact;
    order = previous_error > 0.0 ? std::log2(previous_error / error) : 0.0;
    std::printf("%4dx%dx%d %8d %14.6e %12.4e %8.2f\n", nx, n, n, 6 * nx * n * n, deflection, error, order);
    EXPECT_LT(deflection, exact) << "linear tets are too stiff, never too soft";
    if (previous_error > 0.0) {
      EXPECT_LT(error, previous_error) << "refinement to " << nx << "x" << n;
    }
    previous_error = error;
  }
  EXPECT_LT(previous_error, finest_bound);
  EXPECT_GE(order, 1.0);
}

TEST(CantileverBeam, TipLoadConvergesToEulerBernoulliWithShear) {
  check_mesh_convergence(Load::kTip, "tip load", 0.1);
}

TEST(CantileverBeam, GravityConvergesToEulerBernoulliWithShear) {
  check_mesh_convergence(Load::kGravity, "gravity", 0.1);
}

}  // namespace
}  // namespace rice::fem
