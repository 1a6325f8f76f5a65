#pragma once
// Sparse LU factorization by UMFPACK, for many matrices of one sparsity pattern.

#include <vector>

#include "core/types.h"

namespace fosssim {

/// P R A Q = L U of a square sparse matrix by UMFPACK (SuiteSparse; Davis, "Algorithm 832:
/// UMFPACK V4.3, an unsymmetric-pattern multifrontal method", ACM TOMS 30(2), 2004): dense
/// frontal matrices through the BLAS, partial pivoting, so that any non-singular matrix is
/// factored, symmetric indefinite and non-symmetric alike. analyze() orders a pattern once;
/// factorize() computes the numbers of any matrix of that pattern; solve() reuses them,
/// without allocating, and without iterative refinement (its callers refine with GMRES).
class LuFactor {
 public:
  LuFactor();
  ~LuFactor();
  LuFactor(const LuFactor&) = delete;
  LuFactor& operator=(const LuFactor&) = delete;

  /// Orders and analyses the pattern of A (n×n; values guide the pivot strategy only).
  void analyze(const SparseMatrix& A);
  /// Factors A, which must have the analysed pattern. False when A is numerically singular.
  bool factorize(const SparseMatrix& A);
  bool is_analyzed() const { return symbolic_ != nullptr; }
  bool is_factored() const { return factored_; }

  /// x = A⁻¹ b for the last factored A (b and x of size n, not overlapping).
  void solve(const double* b, double* x) const;

  int size() const { return size_; }
  /// Non-zeros of L and U together.
  double factor_nonzeros() const { return factor_nonzeros_; }
  /// Floating-point operations of the last numeric factorization (UMFPACK's count).
  double factor_flops() const { return factor_flops_; }

 private:
  void free_numeric();

  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  std::vector<double> control_;
  int size_ = 0;
  bool factored_ = false;
  double factor_nonzeros_ = 0.0;
  double factor_flops_ = 0.0;
  mutable std::vector<double> info_;
  mutable std::vector<int> integer_work_;
  mutable std::vector<double> work_;
};

}  // namespace fosssim
