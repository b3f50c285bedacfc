// The patch test (issue 3, §2): an affine displacement imposed on the boundary of an irregular
// tet mesh is reproduced exactly inside by the reference solver's quasi-static mode. Under a
// homogeneous deformation the stress is constant, so the nodal forces of the tets around an
// interior vertex cancel for any material and any strain: the test holds at small strain (the
// classical linear patch test) and at finite strain alike.
#include <gtest/gtest.h>

#include "fem_reference/implicit_solver.hpp"
#include "tests/common/jittered_mesh.hpp"

namespace rice::fem {
namespace {

using xpbd::Mat3;
using xpbd::Vec3;

struct PatchResult {
  double max_error;  ///< max over interior vertices of |x − (A X + b)| [m]
  double scale;      ///< max over vertices of |A X + b − X| [m], the imposed displacement
  NewtonReport report;
};

PatchResult run_patch_test(const Mat3& A, const Vec3& b) {
  const int n = 4;
  const double size = 0.01;
  const xpbd::TetMesh mesh = test_support::jittered_box_mesh(Vec3::Constant(size), n, n, n, 0.2, 11);
  xpbd::Model model;
  model.particles = xpbd::make_particles(mesh, 1000.0);
  xpbd::add_neo_hookean_tets(model, mesh, xpbd::lame_from_young_poisson(1e5, 0.35));
  model.gravity.setZero();
  const Positions target = (mesh.V * A.transpose()).rowwise() + b.transpose();
  std::vector<int> boundary;
  for (int v = 0; v < mesh.V.rows(); ++v) {
    const bool on_face = ((mesh.V.row(v).array() < 1e-12 * size) ||
                          (mesh.V.row(v).array() > (1.0 - 1e-12) * size)).any();
    if (on_face) {
      boundary.push_back(v);
      model.particles.x.row(v) = target.row(v);
    }
  }
  xpbd::pin_particles(model, boundary);
  ImplicitSolver solver(model, {.newton = {.tolerance = 1e-12}});
  PatchResult result{0.0, (target - mesh.V).rowwise().norm().maxCoeff(), solver.solve_static()};
  result.max_error = (model.particles.x - target).rowwise().norm().maxCoeff();
  return result;
}

TEST(PatchTest, AffineBoundaryDisplacementIsReproducedInsideAtSmallStrain) {
  Mat3 A;
  A << 1.001, 0.0004, -0.0002, 0.0003, 0.9995, 0.0006, -0.0001, 0.0002, 1.0007;
  const PatchResult r = run_patch_test(A, Vec3(1e-4, -2e-4, 5e-5));
  EXPECT_TRUE(r.report.converged);
  // Round-off of the Newton solve relative to the imposed displacement.
  EXPECT_LT(r.max_error, 1e-9 * r.scale) << "error " << r.max_error << " m of " << r.scale << " m";
}

TEST(PatchTest, AffineBoundaryDisplacementIsReproducedInsideAtFiniteStrain) {
  Mat3 A;
  A << 1.3, 0.2, 0.0, -0.1, 0.8, 0.15, 0.05, 0.0, 1.1;
  const PatchResult r = run_patch_test(A, Vec3::Zero());
  EXPECT_TRUE(r.report.converged);
  EXPECT_LT(r.max_error, 1e-9 * r.scale) << "error " << r.max_error << " m of " << r.scale << " m";
}

}  // namespace
}  // namespace rice::fem
