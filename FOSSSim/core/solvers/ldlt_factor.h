#pragma once
// Sparse symmetric indefinite factorization by MUMPS, for many matrices of one sparsity pattern.

#include <memory>
#include <vector>

#include "core/types.h"

namespace fosssim {

/// The arithmetic a factor is computed and stored in.
enum class FactorPrecision { kDouble, kSingle };

/// P A Pᵀ = L D Lᵀ of a symmetric sparse matrix, positive definite or not, by MUMPS (Amestoy,
/// Duff, L'Excellent and Koster, "A fully asynchronous multifrontal solver using distributed
/// dynamic scheduling", SIAM J. Matrix Anal. Appl. 23(1), 2001; the sequential library
/// Debian ships): a multifrontal method whose dense fronts run through the BLAS (OpenBLAS,
/// threaded), with 1×1 and 2×2 pivots chosen by threshold pivoting, so that the step
/// matrices a compressed spring makes indefinite are factored at about the cost of a
/// Cholesky factorization. analyze() orders a pattern once; factorize() computes the numbers
/// of any matrix of that pattern; solve() reuses them, without iterative refinement (its
/// callers refine with GMRES). Only the lower triangle of A is read.
///
/// The factor may be computed in single precision (FactorPrecision::kSingle: MUMPS's float
/// library, the matrix rounded to float): about half the time and half the memory of a double
/// factor, and a preconditioner whose error (float round-off times A's condition number) a
/// Krylov method in double removes in a few iterations (Buttari, Dongarra, Kurzak, Luszczek
/// and Tomov, "Using mixed precision for sparse matrix computations to enhance the performance
/// while achieving 64-bit accuracy", ACM TOMS 34(4), 2008, did so with MUMPS). solve() takes
/// and returns doubles in either precision.
///
/// Its result is the same from run to run at the same number of BLAS threads.
class LdltFactor {
 public:
  explicit LdltFactor(FactorPrecision precision = FactorPrecision::kDouble);
  ~LdltFactor();
  LdltFactor(const LdltFactor&) = delete;
  LdltFactor& operator=(const LdltFactor&) = delete;

  /// Orders and analyses the pattern of A (n×n, symmetric; only the lower triangle is read).
  void analyze(const SparseMatrix& A);
  /// Factors A, which must have the analysed pattern. False when A is numerically singular
  /// (in the factor's precision) or, for a single-precision factor, has an entry beyond
  /// float's range.
  bool factorize(const SparseMatrix& A);
  bool is_analyzed() const { return analysed_; }
  bool is_factored() const { return factored_; }

  /// x = A⁻¹ b for the last factored A (b and x of size n; they may be the same memory).
  void solve(const double* b, double* x) const;

  int size() const { return size_; }
  FactorPrecision precision() const { return precision_; }
  /// Entries of the factor (L and D).
  double factor_nonzeros() const { return factor_nonzeros_; }
  /// Floating-point operations of the last numeric factorization (MUMPS's count).
  double factor_flops() const { return factor_flops_; }
  /// Negative eigenvalues of the last factored A (the negative pivots of D).
  int negative_pivots() const { return negative_pivots_; }

  struct Mumps;  // MUMPS's instance in either arithmetic, defined with the code

 private:
  FactorPrecision precision_;
  std::unique_ptr<Mumps> mumps_;
  std::vector<int> rows_, columns_;  // the lower triangle's entries, 1-based
  std::vector<int> slots_;           // where each of them is in A's values
  int size_ = 0;
  bool analysed_ = false;
  bool factored_ = false;
  double factor_nonzeros_ = 0.0;
  double factor_flops_ = 0.0;
  int negative_pivots_ = 0;
};

}  // namespace fosssim
