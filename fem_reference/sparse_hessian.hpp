// The Newton matrix over the free DOFs (dof_map.hpp), stored as an Eigen column-major sparse
// matrix with a pattern fixed once from the forms' stencils, so that CHOLMOD's symbolic
// analysis runs once and each Newton step only refills the values.
//
// Assembly adds dense element blocks in place: the three rows of a particle block sit
// together in every column, found by binary search over the column's block rows. The full
// symmetric matrix is stored (CHOLMOD reads its lower triangle).
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "fem_reference/dof_map.hpp"
#include "fem_reference/form.hpp"

namespace rice::fem {

class SparseHessian {
 public:
  SparseHessian(const DofMap& dofs, const std::vector<Stencils>& stencils);

  void set_zero() { matrix_.coeffs().setZero(); }

  /// Adds weight · local, the Hessian of an element over `particles` (N/3 of them, in the
  /// order of local's rows). Rows and columns of fixed particles are dropped.
  template <int N>
  void add(const int* particles, const Eigen::Matrix<double, N, N>& local, double weight) {
    constexpr int kArity = N / 3;
    for (int b = 0; b < kArity; ++b) {
      const int column = dofs_.first_dof(particles[b]);
      if (column < 0) continue;
      for (int a = 0; a < kArity; ++a) {
        const int row = dofs_.first_dof(particles[a]);
        if (row < 0) continue;
        const int offset = block_offset(row, column);
        for (int c = 0; c < 3; ++c) {
          double* values = matrix_.valuePtr() + matrix_.outerIndexPtr()[column + c] + offset;
          for (int r = 0; r < 3; ++r) values[r] += weight * local(3 * a + r, 3 * b + c);
        }
      }
    }
  }

  /// Adds `shift` to every diagonal entry (the Newton fall-back's regularisation).
  void add_to_diagonal(double shift);
  Eigen::VectorXd diagonal() const;

  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }

 private:
  /// Position of the block row starting at DOF `row` within the column starting at `column`.
  int block_offset(int row, int column) const;

  const DofMap& dofs_;
  Eigen::SparseMatrix<double> matrix_;
  std::vector<int> diagonal_index_;  ///< index into valuePtr() of each diagonal entry
};

}  // namespace rice::fem
