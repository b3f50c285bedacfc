// The compliant constraints of the shared model (xpbd/model.hpp) as the reference solver sees
// them. Each kernel maps an element's local coordinates x (3 per particle) linearly to a
// reduced coordinate y = B x — vec F for a tetrahedron, x0 − x1 for a spring, x itself for an
// attachment — and evaluates the constraint values C(y), their Jacobian ∂C/∂y and each
// ∂²C_r/∂y² with the xpbd kernels, so there is one copy of the constraint math. Because B is
// constant, ∇ₓ = Bᵀ∇_y and ∇ₓ² = Bᵀ∇_y² B (`expand`), and a Hessian projected to PSD in y stays
// PSD in x, at the cost of a 9×9 instead of a 12×12 eigen-decomposition per tet.
#pragma once

#include <array>

#include "xpbd/distance_constraint.hpp"
#include "xpbd/model.hpp"
#include "xpbd/tet_constraint_pair.hpp"
#include "xpbd/tet_stencil.hpp"

namespace rice::fem {

using xpbd::Mat12;
using xpbd::Mat3;
using xpbd::Mat6;
using xpbd::Mat9;
using xpbd::Vec12;
using xpbd::Vec2;
using xpbd::Vec3;
using xpbd::Vec6;
using xpbd::Vec9;

/// Values, Jacobian and per-row Hessians of Rows constraints in a Reduced-dimensional y.
template <int Rows, int Reduced>
struct ConstraintDerivatives {
  Eigen::Matrix<double, Rows, 1> C;
  Eigen::Matrix<double, Rows, Reduced> dC;
  std::array<Eigen::Matrix<double, Reduced, Reduced>, Rows> d2C;
};

/// How many derivatives `evaluate` computes: values only, plus Jacobian, plus Hessians.
enum class Order { kValue = 0, kGradient = 1, kHessian = 2 };

/// Coefficients of a one-row constraint type with `compliance` and `damping` members.
template <class Constraint>
struct ScalarCoefficients {
  static Eigen::Matrix<double, 1, 1> compliance(const Constraint& c) {
    return Eigen::Matrix<double, 1, 1>(c.compliance);
  }
  static Eigen::Matrix<double, 1, 1> damping(const Constraint& c) {
    return Eigen::Matrix<double, 1, 1>(c.damping);
  }
  static double rest_energy(const Constraint&) { return 0.0; }
};

/// Shared by the tet kernels: y = vec(Ds Dm⁻¹), column-major (tet_stencil.hpp).
struct TetReduction {
  static Vec9 reduce(const Vec12& x, const Mat3& Dm_inv) {
    const Mat3 F = xpbd::deformation_gradient(x, Dm_inv);
    return Eigen::Map<const Vec9>(F.data());
  }
  static Vec12 expand(const Vec9& g, const Mat3& Dm_inv) {
    return xpbd::gradient_from_dF(Eigen::Map<const Mat3>(g.data()), Dm_inv);
  }
  static Mat12 expand(const Mat9& H, const Mat3& Dm_inv) { return xpbd::hessian_from_d2F(H, Dm_inv); }
};

/// The elastic pair (C_D, C_H) of one tet, of either material (xpbd/tet_constraint_pair.hpp), y =
/// vec F. Corotated: where C_D = 0 exactly, ∂C_D/∂F and ∂²C_D/∂F² are zero, so the form sees
/// no shear stiffness at that one point (C_D ∂²C_D/∂F² is finite everywhere else).
struct NeoHookeanKernel {
  using Constraint = xpbd::NeoHookeanTet;
  static constexpr int kArity = 4, kRows = 2, kReduced = 9;
  using Derivatives = ConstraintDerivatives<kRows, kReduced>;

  static std::array<int, 4> particles(const Constraint& c) { return c.particles; }
  static Vec9 reduce(const Constraint& c, const Vec12& x) { return TetReduction::reduce(x, c.Dm_inv); }
  static Vec12 expand(const Constraint& c, const Vec9& g) { return TetReduction::expand(g, c.Dm_inv); }
  static Mat12 expand(const Constraint& c, const Mat9& H) { return TetReduction::expand(H, c.Dm_inv); }
  static Vec2 compliance(const Constraint& c) {
    return {c.compliance_deviatoric(), c.compliance_hydrostatic()};
  }
  static Vec2 damping(const Constraint& c) { return {c.beta_deviatoric, c.beta_hydrostatic}; }
  /// The pair's energy at rest, subtracted so that U = 0 there (neo_hookean_constraints.hpp).
  static double rest_energy(const Constraint& c) { return c.rest_energy(); }
  static Derivatives evaluate(const Constraint& c, const Vec9& y, Order order);
};

/// Tet volume C = det(Ds)/6 − V0, y = vec Ds.
struct TetVolumeKernel : ScalarCoefficients<xpbd::TetVolumeConstraint> {
  using Constraint = xpbd::TetVolumeConstraint;
  static constexpr int kArity = 4, kRows = 1, kReduced = 9;
  using Derivatives = ConstraintDerivatives<kRows, kReduced>;

  static std::array<int, 4> particles(const Constraint& c) { return c.particles; }
  static Vec9 reduce(const Constraint&, const Vec12& x) { return TetReduction::reduce(x, Mat3::Identity()); }
  static Vec12 expand(const Constraint&, const Vec9& g) { return TetReduction::expand(g, Mat3::Identity()); }
  static Mat12 expand(const Constraint&, const Mat9& H) { return TetReduction::expand(H, Mat3::Identity()); }
  static Derivatives evaluate(const Constraint& c, const Vec9& y, Order order);
};

/// Spring C = |x0 − x1| − L, y = x0 − x1.
struct DistanceKernel : ScalarCoefficients<xpbd::DistanceConstraint> {
  using Constraint = xpbd::DistanceConstraint;
  static constexpr int kArity = 2, kRows = 1, kReduced = 3;
  using Derivatives = ConstraintDerivatives<kRows, kReduced>;

  static std::array<int, 2> particles(const Constraint& c) { return c.particles; }
  static Vec3 reduce(const Constraint&, const Vec6& x) { return x.head<3>() - x.tail<3>(); }
  static Vec6 expand(const Constraint&, const Vec3& g) { return (Vec6() << g, -g).finished(); }
  static Mat6 expand(const Constraint&, const Mat3& H) {
    return (Mat6() << H, -H, -H, H).finished();
  }
  static Derivatives evaluate(const Constraint& c, const Vec3& y, Order order);
};

/// Attachment C = x − p (three rows, one compliance), y = x. It has no damping.
struct AttachmentKernel {
  using Constraint = xpbd::Attachment;
  static constexpr int kArity = 1, kRows = 3, kReduced = 3;
  using Derivatives = ConstraintDerivatives<kRows, kReduced>;

  static std::array<int, 1> particles(const Constraint& c) { return {c.particle}; }
  static Vec3 reduce(const Constraint&, const Vec3& x) { return x; }
  static Vec3 expand(const Constraint&, const Vec3& g) { return g; }
  static Mat3 expand(const Constraint&, const Mat3& H) { return H; }
  static Vec3 compliance(const Constraint& c) { return Vec3::Constant(c.compliance); }
  static Vec3 damping(const Constraint&) { return Vec3::Zero(); }
  static double rest_energy(const Constraint&) { return 0.0; }
  static Derivatives evaluate(const Constraint& c, const Vec3& y, Order order);
};

}  // namespace rice::fem
