// Tests of LdltFactor (core/solvers/ldlt_factor.h), MUMPS's L D Lᵀ of symmetric matrices.
//
// Math checked:
// - solutions of symmetric positive definite and indefinite systems agree with dense LU of
//   the same matrix to round-off;
// - Sylvester's law of inertia: the number of negative pivots of D equals the number of
//   negative eigenvalues of A (counted by a dense symmetric eigensolver), on matrices with
//   none, a few and many;
// - one analysis serves any number of factorizations of the pattern, with new values, and the
//   workspace kept between factorizations grows for a larger pattern and delayed pivots;
// - a singular matrix is reported, not solved;
// - in single precision: the same inertia, solutions with float's accuracy (residual near
//   float's round-off, and not double's: the factor really is single), and a matrix with an
//   entry beyond float's range refused rather than factored as infinity.

#include "core/solvers/ldlt_factor.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "support/random.h"

namespace fosssim::testing {
namespace {

/// A random symmetric matrix with the sparsity of a 2D grid's 5-point Laplacian (n × n
/// points), diagonal `shift` + a random number in [0, 1), off-diagonal in [-1, 1): `shift`
/// controls how many eigenvalues are negative.
SparseMatrix grid_matrix(int n, double shift, unsigned seed) {
  Random random(seed);
  std::vector<Triplet> triplets;
  const auto index = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      triplets.emplace_back(index(i, j), index(i, j), shift + random.uniform(0.0, 1.0));
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (i + di >= n || j + dj >= n) continue;
        const double value = random.uniform(-1.0, 1.0);
        triplets.emplace_back(index(i, j), index(i + di, j + dj), value);
        triplets.emplace_back(index(i + di, j + dj), index(i, j), value);
      }
    }
  }
  SparseMatrix A(n * n, n * n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

int negative_eigenvalues(const SparseMatrix& A) {
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues();
  return static_cast<int>((eigenvalues.array() < 0.0).count());
}

void expect_factor_solves(const LdltFactor& factor, const SparseMatrix& A, unsigned seed) {
  const Vector b = Random(seed).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
  Vector x(b.size());
  factor.solve(b.data(), x.data());
  const Vector reference = Eigen::MatrixXd(A).partialPivLu().solve(b);
  EXPECT_LE((A * x - b).norm(), 1e-11 * (b.norm() + Eigen::MatrixXd(A).norm() * x.norm()));
  EXPECT_LE((x - reference).norm(), 1e-9 * reference.norm());
}

TEST(LdltFactor, CountsNegativePivotsAsTheMatrixHasNegativeEigenvalues) {
  for (const double shift : {4.5, 0.5, -1.0}) {  // definite, a few negative, many negative
    SCOPED_TRACE(shift);
    const SparseMatrix A = grid_matrix(12, shift, 301);
    const int expected = negative_eigenvalues(A);
    if (shift > 4.0) {
      ASSERT_EQ(expected, 0) << "precondition: definite";
    }
    if (shift < 0.0) {
      ASSERT_GT(expected, 40) << "precondition: strongly indefinite";
    }
    LdltFactor factor;
    factor.analyze(A);
    ASSERT_TRUE(factor.factorize(A));
    EXPECT_EQ(factor.negative_pivots(), expected);
    expect_factor_solves(factor, A, 302);
    EXPECT_GT(factor.factor_nonzeros(), A.nonZeros() / 2.0);
    EXPECT_GT(factor.factor_flops(), 0.0);
  }
}

TEST(LdltFactor, OneAnalysisServesNewValuesOfThePattern) {
  LdltFactor factor;
  factor.analyze(grid_matrix(10, 4.5, 303));
  for (unsigned seed = 304; seed < 308; ++seed) {
    const SparseMatrix A = grid_matrix(10, seed % 2 == 0 ? 4.5 : -0.5, seed);
    ASSERT_TRUE(factor.factorize(A));
    EXPECT_EQ(factor.negative_pivots(), negative_eigenvalues(A));
    expect_factor_solves(factor, A, seed + 100);
  }
}

// The factorization's workspace is kept from one factorization to the next (ldlt_factor.cpp,
// WK_USER) and sized from the analysis: it must grow for a larger pattern analysed later, and
// for pivots delayed beyond the analysis's estimate (a zero diagonal forces 2×2 pivots where
// the analysed matrix needed none).
TEST(LdltFactor, KeptWorkspaceServesALargerPatternAndDelayedPivots) {
  LdltFactor factor;
  const SparseMatrix small = grid_matrix(5, 4.5, 310);
  factor.analyze(small);
  ASSERT_TRUE(factor.factorize(small));
  expect_factor_solves(factor, small, 311);
  const SparseMatrix large = grid_matrix(20, 4.5, 312);
  factor.analyze(large);
  ASSERT_TRUE(factor.factorize(large));
  expect_factor_solves(factor, large, 313);
  SparseMatrix hollow = grid_matrix(20, 0.0, 314);
  for (int k = 0; k < hollow.outerSize(); ++k) {
    for (SparseMatrix::InnerIterator it(hollow, k); it; ++it) {
      if (it.row() == it.col()) it.valueRef() = 0.0;
    }
  }
  ASSERT_TRUE(factor.factorize(hollow));
  EXPECT_EQ(factor.negative_pivots(), negative_eigenvalues(hollow));
  expect_factor_solves(factor, hollow, 315);
  ASSERT_TRUE(factor.factorize(large));  // and back
  expect_factor_solves(factor, large, 316);
}

TEST(LdltFactor, ReportsASingularMatrix) {
  SparseMatrix A = grid_matrix(6, 3.0, 309);
  // Make row and column 7 zero, keeping the entries in the pattern.
  for (int k = 0; k < A.outerSize(); ++k) {
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) {
      if (it.row() == 7 || it.col() == 7) it.valueRef() = 0.0;
    }
  }
  LdltFactor factor;
  factor.analyze(A);
  EXPECT_FALSE(factor.factorize(A));
  EXPECT_FALSE(factor.is_factored());
}

TEST(LdltFactor, SinglePrecisionFactorHasTheSameInertiaAndFloatAccuracy) {
  for (const double shift : {4.5, 0.5, -1.0}) {
    SCOPED_TRACE(shift);
    const SparseMatrix A = grid_matrix(12, shift, 311);
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues();
    ASSERT_GT(eigenvalues.cwiseAbs().minCoeff(), 1e-3) << "precondition: no eigenvalue near 0";
    LdltFactor factor(FactorPrecision::kSingle);
    EXPECT_EQ(factor.precision(), FactorPrecision::kSingle);
    factor.analyze(A);
    ASSERT_TRUE(factor.factorize(A));
    EXPECT_EQ(factor.negative_pivots(), negative_eigenvalues(A));
    const Vector b = Random(312).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
    Vector x(b.size());
    factor.solve(b.data(), x.data());
    const double scale = b.norm() + Eigen::MatrixXd(A).norm() * x.norm();
    const double residual = (A * x - b).norm();
    EXPECT_LE(residual, 1e-5 * scale);
    EXPECT_GT(residual, 1e-12 * scale) << "a double factor's accuracy: not single precision";
  }
}

TEST(LdltFactor, SinglePrecisionRefusesAnEntryBeyondFloatsRange) {
  SparseMatrix A = grid_matrix(6, 4.5, 313);
  A.coeffRef(5, 5) = 1e39;  // a float's largest is about 3.4e38
  LdltFactor single(FactorPrecision::kSingle);
  single.analyze(A);
  EXPECT_FALSE(single.factorize(A));
  EXPECT_FALSE(single.is_factored());
  LdltFactor twice(FactorPrecision::kDouble);
  twice.analyze(A);
  ASSERT_TRUE(twice.factorize(A));
  expect_factor_solves(twice, A, 314);
}

}  // namespace
}  // namespace fosssim::testing
