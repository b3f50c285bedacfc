// One term of the energy that a Newton step minimises (the incremental potential of backward
// Euler, or the potential energy of a quasi-static solve). Modelled on PolyFEM's `Form`
// (src/polyfem/solver/forms/Form.hpp): every term has a value, a gradient and a Hessian, so
// one finite-difference harness checks them all (tests/fem_reference/test_form_derivatives.cpp).
//
// Forms see the positions of all particles (#P by 3); the Newton solver removes the degrees of
// freedom of pinned particles when it assembles (sparse_hessian.hpp).
#pragma once

#include <string>
#include <vector>

#include "xpbd/types.hpp"

namespace rice::fem {

using xpbd::Positions;
class SparseHessian;

/// The particle stencils of a form's elements, `arity` particles each, one after another:
/// the pairs of particles that an element couples are the nonzero blocks of its Hessian.
struct Stencils {
  int arity = 0;
  std::vector<int> particles;
};

class Form {
 public:
  virtual ~Form() = default;

  /// A short name for reports and error messages.
  virtual std::string name() const = 0;

  virtual double value(const Positions& x) const = 0;

  /// gradient += weight · ∇value(x), #P by 3.
  virtual void add_gradient(const Positions& x, double weight, Positions& gradient) const = 0;

  /// hessian += weight · ∇²value(x). With `project`, each element's Hessian is first
  /// projected to the nearest positive semi-definite matrix (psd_projection.hpp), so that
  /// the sum is a descent-safe Newton matrix.
  virtual void add_hessian(const Positions& x, double weight, bool project,
                           SparseHessian& hessian) const = 0;

  /// The stencils whose blocks add_hessian may touch (fixed for the life of the form).
  virtual Stencils stencils() const = 0;

  /// The largest t ≤ 1 for which x + t·dx is certainly admissible (finite energy all along
  /// the way). Forms that are finite everywhere keep the default.
  virtual double max_step(const Positions& /*x*/, const Positions& /*dx*/) const { return 1.0; }
};

}  // namespace rice::fem
