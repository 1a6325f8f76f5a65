#include "core/solvers/symmetric_part.h"

#include <algorithm>
#include <stdexcept>

namespace fosssim {

namespace {

using Index = SparseMatrix::StorageIndex;

/// Walks A's upper triangle in column order, finding A(j, i) for each A(i, j); with `values`,
/// writes the upper triangle of (A + Aᵀ)/2 there. False when A is not structurally symmetric.
///
/// Column j of A holds its upper entries A(i, j), i ≤ j (its head), then A(r, j) for r > j
/// (its tail). The transpose of an upper entry A(i, j), i < j, is A(j, i), in the tail of
/// column i, whose rows j come in increasing order as the columns j are walked in order: one
/// cursor per column, set to the start of its tail once its head is walked, finds every
/// transpose. A tail entry left unvisited at the end has no transpose in a head.
bool walk(const SparseMatrix& A, std::vector<Index>& cursor, double* values) {
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const double* a = A.valuePtr();
  const Eigen::Index n = A.outerSize();
  cursor.resize(static_cast<std::size_t>(n));
  std::size_t slot = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    auto k = outer[j];
    for (; k < outer[j + 1] && inner[k] <= j; ++k) {
      const auto i = inner[k];
      auto t = k;
      if (i != j) {
        t = cursor[i]++;
        if (t >= outer[i + 1] || inner[t] != j) return false;
      }
      if (values != nullptr) values[slot] = 0.5 * (a[k] + a[t]);
      ++slot;
    }
    cursor[j] = k;
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    if (cursor[j] != outer[j + 1]) return false;
  }
  return true;
}

}  // namespace

bool UpperSymmetricPart::is_structurally_symmetric(const SparseMatrix& A) {
  std::vector<Index> cursor;
  return A.rows() == A.cols() && walk(A, cursor, nullptr);
}

bool UpperSymmetricPart::take_pattern(const SparseMatrix& A) {
  if (A.rows() != A.cols()) throw std::logic_error("UpperSymmetricPart: the matrix is not square");
  if (!walk(A, cursor_, nullptr)) {
    upper_ = SparseMatrix();
    return false;
  }
  // Column j's upper entries are its first ones, up to row j.
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const Eigen::Index n = A.outerSize();
  const auto head_end = [&](Eigen::Index j) {
    return std::upper_bound(inner + outer[j], inner + outer[j + 1], j);
  };
  upper_ = SparseMatrix(n, n);
  auto* starts = upper_.outerIndexPtr();
  starts[0] = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    starts[j + 1] = starts[j] + static_cast<Index>(head_end(j) - (inner + outer[j]));
  }
  upper_.resizeNonZeros(starts[n]);
  auto* rows = upper_.innerIndexPtr();
  for (Eigen::Index j = 0; j < n; ++j) rows = std::copy(inner + outer[j], head_end(j), rows);
  std::fill_n(upper_.valuePtr(), upper_.nonZeros(), 0.0);
  return true;
}

bool UpperSymmetricPart::has_pattern(const SparseMatrix& A) const {
  if (A.rows() != upper_.rows() || A.cols() != upper_.cols()) return false;
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const auto* starts = upper_.outerIndexPtr();
  const auto* rows = upper_.innerIndexPtr();
  // Column j of A starts with exactly the rows of U's column j...
  for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
    const auto head_end = outer[j] + (starts[j + 1] - starts[j]);
    if (head_end > outer[j + 1] || (head_end < outer[j + 1] && inner[head_end] <= j) ||
        !std::equal(rows + starts[j], rows + starts[j + 1], inner + outer[j])) {
      return false;
    }
  }
  // ... and the rest of A is their transpose.
  return walk(A, cursor_, nullptr);
}

const SparseMatrix& UpperSymmetricPart::update(const SparseMatrix& A) {
  walk(A, cursor_, upper_.valuePtr());
  return upper_;
}

}  // namespace fosssim
