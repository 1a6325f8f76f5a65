#pragma once
// Factors a symmetric positive definite matrix once, then solves for many right-hand sides.

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <vector>

#include "core/types.h"

namespace fosssim {

/// Cholesky factorization A = L Lᵀ (sparse: P A Pᵀ = L Lᵀ) of a constant SPD matrix, for the
/// local/global solver (libigl's precompute/solve split): factor() once, then solve_in_place()
/// every iteration.
///
/// Dense (Eigen::LLT) suits tiny systems. Sparse uses Eigen::SimplicialLLT with its
/// fill-reducing AMD ordering; its symbolic analysis is kept, so refactor() with the same
/// sparsity pattern (a changed stiffness) only redoes the numeric factorization. The
/// triangular solves are our own: they sweep L once for all C right-hand-side columns together
/// (the x, y and z of every particle), where Eigen's solve sweeps it once per column.
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
  template <int C>
  void solve_sparse(Points<C>& X) const;

  Method method_ = Method::kSparse;
  int size_ = 0;
  Eigen::LLT<Eigen::MatrixXd> dense_;
  Eigen::SimplicialLLT<SparseMatrix> sparse_;
  bool own_sweeps_ = false;       // L's layout is the one solve_sparse expects (else Eigen's solve)
  mutable Eigen::VectorXd work_;  // the permuted right-hand sides, C per row
};

}  // namespace fosssim
