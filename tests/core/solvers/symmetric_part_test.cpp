// Tests of UpperSymmetricPart (core/solvers/symmetric_part.h): the upper triangle of
// (A + Aᵀ)/2 over A's pattern, and the check of structural symmetry.
//
// Math checked: for a random non-symmetric A with a symmetric pattern (some stored zeros, an
// empty column), U holds exactly the entries (i, j), i ≤ j, of A's pattern, each equal to
// 0.5 (A(i, j) + A(j, i)) bit for bit; new values of the same pattern give the new part; a
// pattern missing one transposed entry, above or below the diagonal, is refused.

#include "core/solvers/symmetric_part.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/random.h"

namespace fosssim::testing {
namespace {

/// A random n×n matrix whose pattern is symmetric and whose values are not; every third
/// stored entry of the upper triangle is a stored zero, and column `empty` has no entries.
SparseMatrix random_matrix(int n, int empty, unsigned seed) {
  Random rng(seed);
  std::vector<Triplet> triplets;
  for (int j = 0; j < n; ++j) {
    for (int i = j; i < n; ++i) {
      if (i == empty || j == empty || (i != j && rng.uniform(0.0, 1.0) < 0.6)) continue;
      triplets.emplace_back(i, j, rng.uniform(-1.0, 1.0));
      if (i != j) triplets.emplace_back(j, i, (i + j) % 3 == 0 ? 0.0 : rng.uniform(-1.0, 1.0));
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

void expect_upper_symmetric_part(const SparseMatrix& U, const SparseMatrix& A) {
  ASSERT_EQ(U.rows(), A.rows());
  int expected_entries = 0;
  for (int j = 0; j < A.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      if (it.row() > j) continue;
      ++expected_entries;
      const double expected = 0.5 * (it.value() + A.coeff(j, static_cast<int>(it.row())));
      EXPECT_EQ(U.coeff(it.row(), j), expected) << "(" << it.row() << ", " << j << ")";
    }
  }
  EXPECT_EQ(U.nonZeros(), expected_entries);
}

TEST(UpperSymmetricPart, IsTheUpperTriangleOfTheSymmetricPartOverThePattern) {
  SparseMatrix A = random_matrix(40, 17, 3);
  UpperSymmetricPart part;
  ASSERT_TRUE(UpperSymmetricPart::is_structurally_symmetric(A));
  ASSERT_TRUE(part.take_pattern(A));
  expect_upper_symmetric_part(part.update(A), A);

  for (int k = 0; k < A.nonZeros(); ++k) A.valuePtr()[k] = std::sin(3.0 * k);  // same pattern
  expect_upper_symmetric_part(part.update(A), A);
  EXPECT_EQ(&part.matrix(), &part.update(A));
}

/// A with the entry pair (i, j), (j, i) added (stored zeros) or removed.
SparseMatrix with_pair(const SparseMatrix& A, int i, int j, bool add) {
  std::vector<Triplet> triplets;
  for (int c = 0; c < A.outerSize(); ++c) {
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
      const bool in_pair = (it.row() == i && c == j) || (it.row() == j && c == i);
      if (add || !in_pair) triplets.emplace_back(static_cast<int>(it.row()), c, it.value());
    }
  }
  if (add) {
    triplets.emplace_back(i, j, 0.0);
    triplets.emplace_back(j, i, 0.0);
  }
  SparseMatrix B(A.rows(), A.cols());
  B.setFromTriplets(triplets.begin(), triplets.end());
  return B;
}

TEST(UpperSymmetricPart, RecognisesExactlyTheTakenPattern) {
  SparseMatrix A = random_matrix(30, 7, 5);
  UpperSymmetricPart part;
  ASSERT_TRUE(part.take_pattern(A));
  EXPECT_TRUE(part.has_pattern(A));
  for (int k = 0; k < A.nonZeros(); ++k) A.valuePtr()[k] = 2.0 * k;
  EXPECT_TRUE(part.has_pattern(A));

  int i = 3, j = 0;  // an entry pair of A below and above the diagonal
  while (A.coeff(i, j) == 0.0 && A.coeff(j, i) == 0.0) ++i;
  const SparseMatrix removed = with_pair(A, i, j, false);
  ASSERT_EQ(removed.nonZeros(), A.nonZeros() - 2);
  EXPECT_FALSE(part.has_pattern(removed));
  const SparseMatrix added = with_pair(A, 7, 2, true);  // column 7 is empty
  ASSERT_EQ(added.nonZeros(), A.nonZeros() + 2);
  EXPECT_FALSE(part.has_pattern(added));
  // A lower entry without its upper transpose: the same upper triangle.
  std::vector<Triplet> triplets = {{7, 2, 1.0}};
  for (int c = 0; c < A.outerSize(); ++c) {
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
      triplets.emplace_back(static_cast<int>(it.row()), c, it.value());
    }
  }
  SparseMatrix lopsided(A.rows(), A.cols());
  lopsided.setFromTriplets(triplets.begin(), triplets.end());
  EXPECT_FALSE(part.has_pattern(lopsided));
  const SparseMatrix bigger = random_matrix(31, 7, 5);
  EXPECT_FALSE(part.has_pattern(bigger));
}

TEST(UpperSymmetricPart, RefusesAPatternMissingATransposedEntry) {
  for (const bool drop_upper : {false, true}) {
    const SparseMatrix A = random_matrix(30, 5, 11);
    std::vector<Triplet> kept;
    bool dropped = false;
    for (int j = 0; j < A.outerSize(); ++j) {
      for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
        const bool upper = it.row() < j;
        if (!dropped && it.row() != j && upper == drop_upper && j > 10) {
          dropped = true;
          continue;
        }
        kept.emplace_back(static_cast<int>(it.row()), j, it.value());
      }
    }
    ASSERT_TRUE(dropped);
    SparseMatrix B(A.rows(), A.cols());
    B.setFromTriplets(kept.begin(), kept.end());
    UpperSymmetricPart part;
    EXPECT_FALSE(UpperSymmetricPart::is_structurally_symmetric(B)) << drop_upper;
    EXPECT_FALSE(part.take_pattern(B)) << drop_upper;
  }
}

}  // namespace
}  // namespace fosssim::testing
