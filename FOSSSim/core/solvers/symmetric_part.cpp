#include "core/solvers/symmetric_part.h"

#include <algorithm>
#include <stdexcept>

namespace fosssim {

namespace {

using Index = SparseMatrix::StorageIndex;

/// Walks A's lower triangle in column order, finding A(j, i) for each A(i, j); with `values`,
/// writes the lower triangle of (A + Aᵀ)/2 there. False when A is not structurally symmetric.
///
/// Column j of A holds A(r, j) for r < j (its head), then its lower entries A(i, j), i ≥ j.
/// The transpose of a lower entry A(i, j), i > j, is A(j, i), in the head of column i, whose
/// rows j come in increasing order as the columns j are walked in order: one cursor per
/// column, starting at its first entry, finds every transpose, and when column j is reached
/// the earlier columns have moved its cursor past its whole head.
bool walk(const SparseMatrix& A, std::vector<Index>& cursor, double* values) {
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const double* a = A.valuePtr();
  const Eigen::Index n = A.outerSize();
  cursor.assign(outer, outer + n);
  std::size_t slot = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto first = cursor[j];
    // An upper entry A(r, j) left unvisited has no lower entry A(j, r).
    if (first < outer[j + 1] && inner[first] < j) return false;
    for (auto k = first; k < outer[j + 1]; ++k) {
      const auto i = inner[k];
      auto t = k;
      if (i != j) {
        t = cursor[i]++;
        if (t >= outer[i + 1] || inner[t] != j) return false;
      }
      if (values != nullptr) values[slot] = 0.5 * (a[k] + a[t]);
      ++slot;
    }
  }
  return true;
}

}  // namespace

bool LowerSymmetricPart::is_structurally_symmetric(const SparseMatrix& A) {
  std::vector<Index> cursor;
  return A.rows() == A.cols() && walk(A, cursor, nullptr);
}

bool LowerSymmetricPart::take_pattern(const SparseMatrix& A) {
  if (A.rows() != A.cols()) throw std::logic_error("LowerSymmetricPart: the matrix is not square");
  if (!walk(A, cursor_, nullptr)) {
    lower_ = SparseMatrix();
    return false;
  }
  // Column j's lower entries are its last ones, from the first row ≥ j on.
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const Eigen::Index n = A.outerSize();
  const auto first_lower = [&](Eigen::Index j) {
    return std::lower_bound(inner + outer[j], inner + outer[j + 1], j);
  };
  SparseMatrix lower(n, n);
  auto* starts = lower.outerIndexPtr();
  starts[0] = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    starts[j + 1] = starts[j] + static_cast<int>(inner + outer[j + 1] - first_lower(j));
  }
  lower.resizeNonZeros(starts[n]);
  auto* rows = lower.innerIndexPtr();
  for (Eigen::Index j = 0; j < n; ++j) rows = std::copy(first_lower(j), inner + outer[j + 1], rows);
  std::fill_n(lower.valuePtr(), lower.nonZeros(), 0.0);
  lower_ = std::move(lower);
  return true;
}

const SparseMatrix& LowerSymmetricPart::update(const SparseMatrix& A) {
  walk(A, cursor_, lower_.valuePtr());
  return lower_;
}

}  // namespace fosssim
