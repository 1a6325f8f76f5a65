#pragma once
// Sparse Cholesky factorization by CHOLMOD, for many matrices of one sparsity pattern.

#include <memory>

#include "core/types.h"

namespace fosssim {

/// How CHOLMOD orders the unknowns and stores the factor.
struct CholeskyOptions {
  /// The fill-reducing ordering, computed once per pattern by analyze().
  enum class Ordering {
    kAmd,    ///< approximate minimum degree: a fast analysis
    kMetis,  ///< METIS nested dissection: a slow analysis, less fill on large meshes
  };
  /// How the factor is stored and computed.
  enum class Layout {
    kAuto,        ///< CHOLMOD's rule: supernodal when the factorization has many flops per entry
    kSimplicial,  ///< column by column: little overhead, for small or very sparse factors
    kSupernodal,  ///< dense blocks of columns with BLAS (both cores with a threaded BLAS)
  };
  /// Which triangle of A is read (the other is ignored, and may be absent). CHOLMOD factors
  /// the lower triangle of P A Pᵀ: from an upper triangle it makes that in one permuted
  /// transpose, from a lower one in two, holding two copies of the triangle at once.
  enum class Triangle {
    kLower,
    kUpper,
  };
  Ordering ordering = Ordering::kAmd;
  Layout layout = Layout::kAuto;
  Triangle triangle = Triangle::kLower;
};

/// P A Pᵀ = L Lᵀ of a symmetric positive definite sparse matrix A by CHOLMOD (SuiteSparse;
/// Chen, Davis, Hager and Rajamanickam, "Algorithm 887: CHOLMOD, supernodal sparse Cholesky
/// factorization and update/downdate", ACM TOMS 35(3), 2008), in libigl's precompute/solve
/// style: analyze() orders and analyses a pattern once, factorize() computes the numbers for
/// any matrix of that pattern, solve() reuses the factor for any number of right-hand sides
/// without allocating after its first call. Only one triangle of A is read
/// (CholeskyOptions::Triangle).
///
/// The supernodal layout runs its dense blocks through the BLAS CHOLMOD is linked with
/// (OpenBLAS on Debian, threaded on every core): its result is the same from run to run at
/// the same number of threads.
class CholeskyFactor {
 public:
  explicit CholeskyFactor(CholeskyOptions options = {});
  ~CholeskyFactor();
  CholeskyFactor(const CholeskyFactor&) = delete;
  CholeskyFactor& operator=(const CholeskyFactor&) = delete;

  /// Orders and analyses the pattern of A (n×n, square; only the chosen triangle is read).
  /// Drops any previous factor.
  void analyze(const SparseMatrix& A);
  /// Factors A, which must have the pattern given to analyze() (its values may differ).
  /// Returns false when A is not numerically positive definite; the factor is then unusable
  /// until the next successful factorize().
  bool factorize(const SparseMatrix& A);
  bool is_analyzed() const;
  bool is_factored() const { return factored_; }

  /// X = A⁻¹ B for the last factored A. B and X are n×columns, column-major (they may be the
  /// same memory).
  void solve(const double* B, double* X, int columns) const;
  /// A⁻¹ b.
  Vector solve(const Vector& b) const;

  int size() const { return size_; }
  /// Non-zeros of L (the factor's memory is about 12 bytes each).
  double factor_nonzeros() const;
  /// Floating-point operations of one numeric factorization (CHOLMOD's count).
  double factor_flops() const;
  /// True when the factor is stored supernodally.
  bool is_supernodal() const;

 private:
  struct Cholmod;  // CHOLMOD's workspace and factor, kept out of this header
  CholeskyOptions options_;
  std::unique_ptr<Cholmod> cholmod_;
  int size_ = 0;
  bool factored_ = false;
};

}  // namespace fosssim
