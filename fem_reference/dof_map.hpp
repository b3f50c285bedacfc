// Degrees of freedom of the reference solver: three per free particle, none for a pinned one.
// Pinned particles are removed from the linear systems, not penalised (issue 3, §1).
#pragma once

#include <vector>

#include "xpbd/types.hpp"

namespace rice::fem {

using xpbd::Positions;

class DofMap {
 public:
  /// `fixed[i]` true removes particle i's three coordinates.
  explicit DofMap(const std::vector<bool>& fixed);

  int dof_count() const { return dof_count_; }
  int particle_count() const { return static_cast<int>(first_dof_.size()); }
  /// Index of particle i's x coordinate among the free DOFs, or −1 when it is fixed.
  int first_dof(int particle) const { return first_dof_[particle]; }
  bool is_free(int particle) const { return first_dof_[particle] >= 0; }

  /// The free coordinates of a #P by 3 field, as one vector.
  Eigen::VectorXd gather(const Positions& field) const;
  /// field += scale · dofs on the free particles; fixed rows are untouched.
  void scatter_add(const Eigen::VectorXd& dofs, double scale, Positions& field) const;

 private:
  std::vector<int> first_dof_;
  int dof_count_ = 0;
};

}  // namespace rice::fem
