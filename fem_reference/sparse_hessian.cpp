// Fixed-pattern assembly of the Newton matrix; see sparse_hessian.hpp.
#include "fem_reference/sparse_hessian.hpp"

#include <algorithm>
#include <cassert>

namespace rice::fem {

SparseHessian::SparseHessian(const DofMap& dofs, const std::vector<Stencils>& stencils)
    : dofs_(dofs) {
  // Block pattern over free particles: every pair that shares an element, plus the diagonal.
  const int particle_count = dofs.particle_count();
  std::vector<std::vector<int>> block_rows(particle_count);
  for (int i = 0; i < particle_count; ++i)
    if (dofs.is_free(i)) block_rows[i].push_back(i);
  for (const Stencils& s : stencils) {
    const size_t elements = s.arity > 0 ? s.particles.size() / s.arity : 0;
    for (size_t e = 0; e < elements; ++e) {
      const int* p = s.particles.data() + e * s.arity;
      for (int a = 0; a < s.arity; ++a)
        for (int b = 0; b < s.arity; ++b)
          if (dofs.is_free(p[a]) && dofs.is_free(p[b])) block_rows[p[b]].push_back(p[a]);
    }
  }
  // Free particles are numbered in particle order, so sorting by particle sorts by DOF.
  size_t nonzeros = 0;
  for (auto& rows : block_rows) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    nonzeros += 9 * rows.size();
  }
  const int n = dofs.dof_count();
  matrix_.resize(n, n);
  matrix_.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
  int* outer = matrix_.outerIndexPtr();
  int* inner = matrix_.innerIndexPtr();
  int entry = 0;
  for (int j = 0; j < particle_count; ++j) {
    if (!dofs.is_free(j)) continue;
    for (int c = 0; c < 3; ++c) {
      outer[dofs.first_dof(j) + c] = entry;
      for (int i : block_rows[j])
        for (int r = 0; r < 3; ++r) inner[entry++] = dofs.first_dof(i) + r;
    }
  }
  outer[n] = entry;
  matrix_.coeffs().setZero();
  diagonal_index_.resize(n);
  for (int k = 0; k < n; ++k) {
    const int* begin = inner + outer[k];
    const int* end = inner + outer[k + 1];
    const int* found = std::lower_bound(begin, end, k);
    assert(found != end && *found == k);
    diagonal_index_[k] = static_cast<int>(found - inner);
  }
}

int SparseHessian::block_offset(int row, int column) const {
  const int* inner = matrix_.innerIndexPtr();
  const int begin = matrix_.outerIndexPtr()[column];
  int lo = 0, hi = (matrix_.outerIndexPtr()[column + 1] - begin) / 3;
  while (lo < hi) {  // first block whose first row is ≥ row
    const int mid = (lo + hi) / 2;
    if (inner[begin + 3 * mid] < row) lo = mid + 1;
    else hi = mid;
  }
  assert(inner[begin + 3 * lo] == row && "element block outside the Hessian's pattern");
  return 3 * lo;
}

void SparseHessian::add_to_diagonal(double shift) {
  for (int index : diagonal_index_) matrix_.valuePtr()[index] += shift;
}

Eigen::VectorXd SparseHessian::diagonal() const {
  Eigen::VectorXd d(diagonal_index_.size());
  for (size_t k = 0; k < diagonal_index_.size(); ++k) d[k] = matrix_.valuePtr()[diagonal_index_[k]];
  return d;
}

}  // namespace rice::fem
