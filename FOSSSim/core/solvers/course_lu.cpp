#include "core/solvers/course_lu.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace fosssim {

namespace {
/// The substitutions work on blocks of this many unknowns.
constexpr int kPanel = 8;
}  // namespace

bool CourseLu::factor(const DenseMatrix& A) {
  assert(A.rows() == A.cols());
  const int n = static_cast<int>(A.rows());
  lu_ = A;
  rows_.assign(static_cast<std::size_t>(n), 0);
  columns_.assign(static_cast<std::size_t>(n), 0);
  double threshold = 0.0;
  for (int k = 0; k < n; ++k) {
    // The pivot: largest magnitude, column by column from (k, k); only a strictly larger value
    // replaces the one kept, so ties go to the first in that order.
    int pivot_row = k;
    int pivot_col = k;
    double biggest = std::abs(lu_(k, k));
    for (int j = k; j < n; ++j) {
      for (int i = k; i < n; ++i) {
        const double magnitude = std::abs(lu_(i, j));
        if (magnitude > biggest) {
          biggest = magnitude;
          pivot_row = i;
          pivot_col = j;
        }
      }
    }
    if (k == 0) threshold = biggest * 0x1p-52;
    if (!(biggest > 0.0) || !std::isfinite(biggest) || biggest < threshold) return false;
    rows_[static_cast<std::size_t>(k)] = pivot_row;
    columns_[static_cast<std::size_t>(k)] = pivot_col;
    if (pivot_row != k) lu_.row(k).swap(lu_.row(pivot_row));
    if (pivot_col != k) lu_.col(k).swap(lu_.col(pivot_col));
    if (k == n - 1) break;
    const double reciprocal = 1.0 / lu_(k, k);
    for (int i = k + 1; i < n; ++i) lu_(i, k) = lu_(i, k) * reciprocal;
    for (int j = k + 1; j < n; ++j) {
      const double pivot_row_entry = lu_(k, j);
      for (int i = k + 1; i < n; ++i) lu_(i, j) = lu_(i, j) - lu_(i, k) * pivot_row_entry;
    }
  }
  return true;
}

void course_panel_product(const DenseMatrix& A, int row_begin, int row_end, int col_begin,
                          int col_end, const double* t, double* res) {
  const int rows = row_end - row_begin;
  const int paired_end = row_begin + (rows / 2) * 2;
  int c = col_begin;
  for (; c + 4 <= col_end; c += 4) {
    const double t0 = t[c - col_begin], t1 = t[c + 1 - col_begin];
    const double t2 = t[c + 2 - col_begin], t3 = t[c + 3 - col_begin];
    for (int r = row_begin; r < paired_end; ++r) {
      res[r] = res[r] + ((A(r, c) * t0 + A(r, c + 1) * t1) + (A(r, c + 2) * t2 + A(r, c + 3) * t3));
    }
    if (paired_end < row_end) {
      const int r = paired_end;
      res[r] = A(r, c) * t0 + res[r];
      res[r] = A(r, c + 1) * t1 + res[r];
      res[r] = A(r, c + 2) * t2 + res[r];
      res[r] = A(r, c + 3) * t3 + res[r];
    }
  }
  for (; c < col_end; ++c) {
    const double tc = t[c - col_begin];
    for (int r = row_begin; r < row_end; ++r) res[r] = A(r, c) * tc + res[r];
  }
}

Vector CourseLu::solve(const Vector& b) const {
  const int n = static_cast<int>(lu_.rows());
  assert(b.size() == n);
  Vector c = b;
  for (int k = 0; k < n; ++k) std::swap(c[k], c[rows_[static_cast<std::size_t>(k)]]);
  double negated[kPanel];

  // Forward, unit lower L, panels of 8 from the top.
  for (int p = 0; p < n; p += kPanel) {
    const int e = std::min(p + kPanel, n);
    for (int i = p; i < e; ++i) {
      for (int s = i + 1; s < e; ++s) c[s] = c[s] - lu_(s, i) * c[i];
    }
    if (e < n) {
      for (int j = p; j < e; ++j) negated[j - p] = -c[j];
      course_panel_product(lu_, e, n, p, e, negated, c.data());
    }
  }

  // Backward, U, panels of 8 from the bottom.
  for (int p = n; p > 0;) {
    const int s = std::max(p - kPanel, 0);
    for (int i = p - 1; i >= s; --i) {
      c[i] = c[i] / lu_(i, i);
      for (int t = s; t < i; ++t) c[t] = c[t] - lu_(t, i) * c[i];
    }
    if (s > 0) {
      for (int j = s; j < p; ++j) negated[j - s] = -c[j];
      course_panel_product(lu_, 0, s, s, p, negated, c.data());
    }
    p = s;
  }

  for (int k = n - 1; k >= 0; --k) std::swap(c[k], c[columns_[static_cast<std::size_t>(k)]]);
  return c;
}

double two_lane_norm(const Vector& x) {
  const Eigen::Index n = x.size();
  if (n == 0) return 0.0;
  if (n == 1) return std::sqrt(x[0] * x[0]);
  double even = x[0] * x[0];
  double odd = x[1] * x[1];
  Eigen::Index k = 2;
  for (; k + 1 < n; k += 2) {
    even = even + x[k] * x[k];
    odd = odd + x[k + 1] * x[k + 1];
  }
  double sum = even + odd;
  if (k < n) sum = sum + x[k] * x[k];
  return std::sqrt(sum);
}

}  // namespace fosssim
