#pragma once
// Factors a symmetric positive definite matrix once, then solves for many right-hand sides.

#include <Eigen/Cholesky>
#include <optional>

#include "core/solvers/cholesky_factor.h"
#include "core/types.h"

namespace fosssim {

/// Cholesky factorization A = L Lᵀ (sparse: P A Pᵀ = L Lᵀ) of a constant SPD matrix, for the
/// local/global solver and its accelerations (libigl's precompute/solve split): factor() once,
/// then solve_in_place() every iteration.
///
/// Dense (Eigen::LLT) suits tiny systems. Sparse is CHOLMOD's (CholeskyFactor): the ordering
/// and symbolic analysis are kept, so refactor() with the same sparsity pattern (a changed
/// stiffness) only redoes the numeric factorization, and every solve takes all C columns (the
/// x, y and z of every particle) through the factor together.
class SpdSolver {
 public:
  enum class Method { kDense, kSparse };

  /// Analyses and factors A (n×n, symmetric; the full matrix, both triangles). Returns false
  /// when A is not numerically positive definite.
  bool factor(const SparseMatrix& A, Method method);
  /// Factors A again, reusing the symbolic analysis when the method is sparse and A has the
  /// sparsity pattern of the last factor() call.
  bool refactor(const SparseMatrix& A);

  /// Overwrites X (n×C, row-major) with A⁻¹ X.
  template <int C>
  void solve_in_place(Points<C>& X) const;

  Method method() const { return method_; }
  /// Non-zeros of the Cholesky factor L (dense: n(n+1)/2).
  long factor_nonzeros() const;

 private:
  Method method_ = Method::kSparse;
  int size_ = 0;
  Eigen::LLT<Eigen::MatrixXd> dense_;
  std::optional<CholeskyFactor> sparse_;
  SparseMatrix::Index pattern_nonzeros_ = 0;
  mutable Eigen::MatrixXd columns_;  // the right-hand sides, column-major, for CHOLMOD
};

}  // namespace fosssim
