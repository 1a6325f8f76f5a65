// Tests of CourseLu, course_panel_product and two_lane_norm (docs/solvers.md, 'The course-exact
// dense path') against their rules, on matrices made by hand so that each rule decides a bit.
//
// Math checked:
// - pivot scan: of equal magnitudes the first in column-major order from (k, k) wins
//   ([[1, 2], [-2, 1]] pivots on (1, 0), not (0, 1));
// - the multipliers are the column times the reciprocal of the pivot: [[7, 1], [5, 2]] gives
//   L_10 = 5 × (1/7) = 0.7142857142857142, where 5 ÷ 7 = 0.7142857142857143;
// - the panel product sums four columns as ((a t + a t) + (a t + a t)) for pairs of rows, one by
//   one for an odd last row and for leftover columns: with t = 1 and a row (1, 2⁻⁵³, 2⁻⁵³, 2⁻⁵³)
//   the pairs get 1 + 2⁻⁵², the odd row 1;
// - the substitutions pass panels of 8 unknowns through that product: a unit lower triangular
//   system of 11 unknowns gives x_8 = 1 + 2⁻⁵² (paired row) and x_10 = 1 (odd row), an upper one
//   of 10 unknowns x_0 = 1 + 2⁻⁵² (panels from the bottom: [2, 10) then [0, 2));
// - random systems of 2 to 64 unknowns (one with a fixed particle's identity row) are solved to
//   round-off, ‖A x - b‖ ≤ 1e-13 ‖A‖ ‖x‖, and a singular matrix is reported;
// - the two-lane norm: 2 and eight squares of 2⁻⁵² at odd places give 2 + 2⁻⁵¹, where the
//   sequential sum gives 2.

#include "core/solvers/course_lu.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/random.h"

namespace fosssim::testing {
namespace {

TEST(CourseLu, PivotTiesGoToTheFirstInColumnMajorOrder) {
  DenseMatrix A(2, 2);
  A << 1.0, 2.0, -2.0, 1.0;
  CourseLu lu;
  ASSERT_TRUE(lu.factor(A));
  EXPECT_EQ(lu.row_transpositions()[0], 1);
  EXPECT_EQ(lu.column_transpositions()[0], 0);
  EXPECT_EQ(lu.packed()(0, 0), -2.0);
}

TEST(CourseLu, MultipliersUseTheReciprocalOfThePivot) {
  DenseMatrix A(2, 2);
  A << 7.0, 1.0, 5.0, 2.0;
  CourseLu lu;
  ASSERT_TRUE(lu.factor(A));
  EXPECT_EQ(lu.row_transpositions()[0], 0);
  EXPECT_EQ(lu.packed()(1, 0), 0.7142857142857142);
  EXPECT_NE(lu.packed()(1, 0), 5.0 / 7.0);
  EXPECT_EQ(lu.packed()(1, 1), 2.0 - 0.7142857142857142 * 1.0);
}

TEST(CourseLu, PanelProductGroupsFourColumnsForPairsOfRows) {
  const double tiny = 0x1p-53;
  DenseMatrix A = DenseMatrix::Zero(3, 5);
  for (int r = 0; r < 3; ++r) A.row(r) << 1.0, tiny, tiny, tiny, 0.0;
  const double t[5] = {1.0, 1.0, 1.0, 1.0, 1.0};
  double res[3] = {0.0, 0.0, 0.0};
  course_panel_product(A, 0, 3, 0, 5, t, res);
  EXPECT_EQ(res[0], 1.0 + 0x1p-52);
  EXPECT_EQ(res[1], 1.0 + 0x1p-52);
  EXPECT_EQ(res[2], 1.0);  // the odd row: four products one after the other
  // A leftover column goes one product at a time into every row.
  DenseMatrix B = DenseMatrix::Zero(2, 5);
  B.col(4).setConstant(tiny);
  double more[2] = {1.0, 1.0};
  course_panel_product(B, 0, 2, 0, 5, t, more);
  EXPECT_EQ(more[0], 1.0);
}

TEST(CourseLu, ForwardSubstitutionPassesPanelsOfEightThroughTheProduct) {
  const double tiny = 0x1p-53;
  const int n = 11;
  DenseMatrix A = DenseMatrix::Identity(n, n);
  for (int r : {8, 10}) A.row(r).head(4) << 1.0, tiny, tiny, tiny;
  Vector b = Vector::Zero(n);
  b.head(4).setConstant(-1.0);
  CourseLu lu;
  ASSERT_TRUE(lu.factor(A));
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(lu.row_transpositions()[k], k);
    EXPECT_EQ(lu.column_transpositions()[k], k);
  }
  const Vector x = lu.solve(b);
  EXPECT_EQ(x[8], 1.0 + 0x1p-52);  // rows 8, 9 are a pair
  EXPECT_EQ(x[10], 1.0);           // row 10 is odd
  EXPECT_EQ(x[0], -1.0);
}

TEST(CourseLu, BackwardSubstitutionRunsPanelsFromTheBottom) {
  const double tiny = 0x1p-53;
  const int n = 10;
  DenseMatrix A = DenseMatrix::Identity(n, n);
  A.row(0).segment(2, 4) << 1.0, tiny, tiny, tiny;
  Vector b = Vector::Zero(n);
  b.segment(2, 4).setConstant(-1.0);
  CourseLu lu;
  ASSERT_TRUE(lu.factor(A));
  const Vector x = lu.solve(b);
  // Panel [2, 10) reaches rows 0 and 1 through the grouped product.
  EXPECT_EQ(x[0], 1.0 + 0x1p-52);
  EXPECT_EQ(x[2], -1.0);
}

TEST(CourseLu, SolvesRandomSystemsToRoundOff) {
  Random random(23);
  for (int n : {2, 6, 10, 16, 17, 56, 64}) {
    DenseMatrix A(n, n);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) A(r, c) = random.uniform(-1.0, 1.0);
    }
    if (n >= 6) {  // a fixed DOF's identity row and column
      A.row(3).setZero();
      A.col(3).setZero();
      A(3, 3) = 1.0;
    }
    Vector b(n);
    for (int k = 0; k < n; ++k) b[k] = random.uniform(-1.0, 1.0);
    CourseLu lu;
    ASSERT_TRUE(lu.factor(A)) << n;
    const Vector x = lu.solve(b);
    EXPECT_LE((A * x - b).norm(), 1e-13 * A.norm() * x.norm()) << n << " unknowns";
    EXPECT_EQ(lu.solve(b), x) << "deterministic";
  }
}

TEST(CourseLu, ReportsASingularMatrix) {
  DenseMatrix A(3, 3);
  A << 1.0, 2.0, 3.0, 2.0, 4.0, 6.0, 0.5, 1.0, 1.5;
  CourseLu lu;
  EXPECT_FALSE(lu.factor(A));
  EXPECT_FALSE(lu.factor(DenseMatrix::Zero(2, 2)));
}

TEST(TwoLaneNorm, SumsEvenAndOddEntriesApart) {
  Vector x = Vector::Zero(17);
  x[0] = 2.0;
  for (int k = 1; k < 17; k += 2) x[k] = 0x1p-26;
  double sequential = 0.0;
  for (int k = 0; k < 17; ++k) sequential = sequential + x[k] * x[k];
  EXPECT_EQ(std::sqrt(sequential), 2.0);
  EXPECT_EQ(two_lane_norm(x), 2.0 + 0x1p-51);
  EXPECT_EQ(two_lane_norm(Vector::Zero(0)), 0.0);
  EXPECT_EQ(two_lane_norm(Vector::Constant(1, -3.0)), 3.0);
  EXPECT_EQ(two_lane_norm(Vector::Constant(3, 2.0)), std::sqrt(12.0));
}

}  // namespace
}  // namespace fosssim::testing
