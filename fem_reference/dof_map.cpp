// Free-DOF numbering; see dof_map.hpp.
#include "fem_reference/dof_map.hpp"

namespace rice::fem {

DofMap::DofMap(const std::vector<bool>& fixed) : first_dof_(fixed.size(), -1) {
  for (size_t i = 0; i < fixed.size(); ++i)
    if (!fixed[i]) {
      first_dof_[i] = dof_count_;
      dof_count_ += 3;
    }
}

Eigen::VectorXd DofMap::gather(const Positions& field) const {
  Eigen::VectorXd dofs(dof_count_);
  for (int i = 0; i < particle_count(); ++i)
    if (first_dof_[i] >= 0) dofs.segment<3>(first_dof_[i]) = field.row(i).transpose();
  return dofs;
}

void DofMap::scatter_add(const Eigen::VectorXd& dofs, double scale, Positions& field) const {
  for (int i = 0; i < particle_count(); ++i)
    if (first_dof_[i] >= 0) field.row(i) += scale * dofs.segment<3>(first_dof_[i]).transpose();
}

}  // namespace rice::fem
