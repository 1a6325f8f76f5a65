#pragma once
// Solves the implicit step system A x = b with a sparse factorization that is correct for A.

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <optional>
#include <vector>

#include "core/types.h"

namespace fosssim {

/// Which factorization solved the last system.
enum class Factorization { kLDLT, kLU };

/// Factorizes and solves the step matrix A = M + h² hessX + h hessV.
///
/// A is symmetric when every force's Jacobians are (springs without damping, gravity, drag);
/// then a sparse LDLᵀ (no pivoting) is tried first and its answer accepted only when the
/// residual ‖Ax - b‖ is at round-off level, because a compressed spring or Newtonian gravity can
/// make A indefinite. Otherwise, and as the fallback, sparse LU with partial pivoting is used,
/// which is correct for the non-symmetric A of damped springs and vortices.
/// The symbolic analysis is reused while A's sparsity pattern stays the same.
class StepSolver {
 public:
  /// symmetric: whether A is known to be symmetric (SceneModel::has_symmetric_jacobians).
  explicit StepSolver(bool symmetric) : symmetric_(symmetric) {}

  /// Returns x with A x = b, or nullopt when A is numerically singular.
  std::optional<Vector> solve(const SparseMatrix& A, const Vector& b);

  /// The factorization used by the last successful solve.
  Factorization last_factorization() const { return last_; }

 private:
  bool same_pattern(const SparseMatrix& A) const;
  std::optional<Vector> solve_ldlt(const SparseMatrix& A, const Vector& b);
  std::optional<Vector> solve_lu(const SparseMatrix& A, const Vector& b);

  bool symmetric_;
  Factorization last_ = Factorization::kLU;
  std::vector<SparseMatrix::StorageIndex> outer_, inner_;  // pattern of the analysed matrix
  bool ldlt_analysed_ = false;
  bool lu_analysed_ = false;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace fosssim
