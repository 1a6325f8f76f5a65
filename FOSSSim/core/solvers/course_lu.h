#pragma once
// The dense LU with full pivoting that the course's reference programs solve every step system
// with, written out so that its results are the course's bit for bit (docs/solvers.md,
// 'The course-exact dense path').

#include <Eigen/Core>
#include <vector>

#include "core/types.h"

namespace fosssim {

using DenseMatrix = Eigen::MatrixXd;

/// The largest step system solved the course's way (dense, CourseLu) under SolverChoice::kAuto:
/// 2D scenes of at most 32 particles. The course's scenes have at most 56 unknowns; a dense
/// factorization of 64 unknowns takes about 90,000 multiply-adds, no more than the sparse path,
/// while larger systems, and every 3D one, keep FOSSSim's sparse solvers.
inline constexpr int kCourseLuMaxUnknowns = 64;

/// P A Q = L U of a small dense matrix, with full pivoting, in a fixed order of floating-point
/// operations (that of the course's Eigen 2.91 FullPivLU on SSE2):
/// - step k takes the pivot of largest magnitude among rows and columns k.., scanning column by
///   column and keeping the first of equal magnitudes; it swaps whole rows, then whole columns;
/// - the column below the pivot is multiplied by the reciprocal of the pivot (not divided), and
///   the trailing block updated as a_ij - a_ik a_kj, column by column;
/// - solve() runs the forward and backward substitutions in panels of 8 unknowns, each panel
///   passing its result to the remaining rows through a product summed in groups of four columns
///   (course_lu.cpp says exactly how).
/// O(n³) work and n² storage: meant for the course's small 2D systems (kCourseLuMaxUnknowns),
/// never for large ones.
class CourseLu {
 public:
  /// Factors A (square). Returns false when A is numerically singular: a pivot below
  /// 2⁻⁵² times the first pivot's magnitude, or no nonzero finite pivot.
  bool factor(const DenseMatrix& A);
  /// x with A x = b, for the A of the last successful factor().
  Vector solve(const Vector& b) const;

  /// The packed factors (unit lower L below the diagonal, U on and above it) and the
  /// transpositions, for tests.
  const DenseMatrix& packed() const { return lu_; }
  const std::vector<int>& row_transpositions() const { return rows_; }
  const std::vector<int>& column_transpositions() const { return columns_; }

 private:
  DenseMatrix lu_;
  std::vector<int> rows_;
  std::vector<int> columns_;
};

/// res_r += Σ_c A(r, c) t_c over rows [row_begin, row_end) and columns [col_begin, col_end) of A,
/// in the course's order: columns in groups of four, each pair of rows taking
/// ((A_r0 t0 + A_r1 t1) + (A_r2 t2 + A_r3 t3)) at once, an odd last row the four products one by
/// one, and leftover columns one at a time. Exposed for tests.
void course_panel_product(const DenseMatrix& A, int row_begin, int row_end, int col_begin,
                          int col_end, const double* t, double* res);

/// √(Σ δ_k²) summed as two interleaved partial sums (even and odd entries), added at the end,
/// an odd length's last square after that: the norm of the course's Newton test.
double two_lane_norm(const Vector& x);

}  // namespace fosssim
