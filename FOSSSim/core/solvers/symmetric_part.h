#pragma once
// The lower triangle of a sparse matrix's symmetric part, for a Cholesky factorization.

#include <vector>

#include "core/types.h"

namespace fosssim {

/// L = the lower triangle of (A + Aᵀ)/2, diagonal included, for matrices A of one
/// structurally symmetric pattern: what CHOLMOD reads to factor the symmetric part of a
/// non-symmetric step matrix, in half the memory of the whole symmetric part and with no
/// table of transposed slots. Each entry is 0.5 (A(i, j) + A(j, i)) with (i, j) in the lower
/// triangle, computed in one pass over A's columns.
class LowerSymmetricPart {
 public:
  /// Whether every (i, j) stored in A comes with (j, i).
  static bool is_structurally_symmetric(const SparseMatrix& A);
  /// Takes A's pattern (square). False when A is not structurally symmetric (some (i, j)
  /// is stored without (j, i)): the pattern is then not taken.
  bool take_pattern(const SparseMatrix& A);
  /// L for A, which must have the taken pattern.
  const SparseMatrix& update(const SparseMatrix& A);
  const SparseMatrix& matrix() const { return lower_; }

 private:
  SparseMatrix lower_;
  std::vector<SparseMatrix::StorageIndex> cursor_;  // workspace of a pass over A
};

}  // namespace fosssim
