#pragma once
// The upper triangle of a sparse matrix's symmetric part, for a Cholesky factorization.

#include <vector>

#include "core/types.h"

namespace fosssim {

/// U = the upper triangle of (A + Aᵀ)/2, diagonal included, for matrices A of one
/// structurally symmetric pattern: what CHOLMOD reads to factor the symmetric part of a
/// non-symmetric step matrix. Half the memory of the whole symmetric part, with no table of
/// transposed slots; and CHOLMOD permutes an upper triangle into the form it factors in one
/// pass, where a lower one takes two (CholeskyOptions::Triangle). Each entry is
/// 0.5 (A(i, j) + A(j, i)), computed in one pass over A's columns.
class UpperSymmetricPart {
 public:
  /// Whether every (i, j) stored in A comes with (j, i).
  static bool is_structurally_symmetric(const SparseMatrix& A);
  /// Takes A's pattern (square). False when A is not structurally symmetric: the pattern is
  /// then not taken.
  bool take_pattern(const SparseMatrix& A);
  /// Whether A has the taken pattern (exactly: A's stored entries are those of U and Uᵀ).
  bool has_pattern(const SparseMatrix& A) const;
  /// U for A, which must have the taken pattern.
  const SparseMatrix& update(const SparseMatrix& A);
  const SparseMatrix& matrix() const { return upper_; }

 private:
  SparseMatrix upper_;
  mutable std::vector<SparseMatrix::StorageIndex> cursor_;  // workspace of a pass over A
};

}  // namespace fosssim
