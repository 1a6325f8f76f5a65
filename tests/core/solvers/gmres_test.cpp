// Tests of Gmres (core/solvers/gmres.h).
//
// Math checked: with an exact preconditioner (M = A) one iteration solves A x = b; with a
// nearby one a few do, to the tolerance, and the answer agrees with dense LU; on a
// non-symmetric matrix with no preconditioner, n iterations solve an n × n system (the Krylov
// space is then the whole space); with give_up_early, a preconditioner too poor to reach the
// tolerance in the allowed iterations is dropped after a few of them, and a good one is not.

#include "core/solvers/gmres.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "support/random.h"

namespace fosssim::testing {
namespace {

/// A non-symmetric tridiagonal n × n matrix with diagonal `diagonal`, super-diagonal 1 and
/// sub-diagonal -0.5.
SparseMatrix tridiagonal(int n, double diagonal) {
  std::vector<Triplet> triplets;
  for (int i = 0; i < n; ++i) {
    triplets.emplace_back(i, i, diagonal);
    if (i + 1 < n) {
      triplets.emplace_back(i, i + 1, 1.0);
      triplets.emplace_back(i + 1, i, -0.5);
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

TEST(Gmres, SolvesInOneIterationWithAnExactPreconditionerAndInAFewWithANearbyOne) {
  const SparseMatrix A = tridiagonal(50, 3.0);
  const Vector b = Random(401).uniform_vector(50, -1.0, 1.0);
  const Eigen::MatrixXd dense_A(A);
  const Vector reference = dense_A.partialPivLu().solve(b);
  for (const double nearby : {3.0, 3.05}) {
    SCOPED_TRACE(nearby);
    const Eigen::PartialPivLU<Eigen::MatrixXd> factor(Eigen::MatrixXd(tridiagonal(50, nearby)));
    const auto precondition = [&](const double* r, double* z) {
      Eigen::Map<Vector>(z, 50) = factor.solve(Eigen::Map<const Vector>(r, 50));
    };
    Gmres gmres;
    Vector x = Vector::Zero(50);
    const KrylovResult result = gmres.solve(A, b, x, precondition, 1e-12 * b.norm(), 30);
    EXPECT_TRUE(result.converged);
    if (nearby == 3.0) {
      EXPECT_EQ(result.iterations, 1);
    }
    EXPECT_LE(result.iterations, 8);
    EXPECT_LE((x - reference).norm(), 1e-10 * reference.norm());
  }
}

TEST(Gmres, SolvesAnNByNSystemInNIterationsWithoutPreconditioner) {
  constexpr int n = 12;
  const SparseMatrix A = tridiagonal(n, 0.1);  // poorly conditioned, non-symmetric
  const Vector b = Random(402).uniform_vector(n, -1.0, 1.0);
  const auto identity = [](const double* r, double* z) { std::copy(r, r + n, z); };
  Gmres gmres;
  Vector x = Vector::Zero(n);
  const KrylovResult result = gmres.solve(A, b, x, identity, 1e-10 * b.norm(), n);
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.iterations, n);
  EXPECT_LE((A * x - b).norm(), 1e-10 * b.norm());
}

TEST(Gmres, GivesUpEarlyOnAPreconditionerThatCannotReachTheTolerance) {
  constexpr int n = 400;
  const SparseMatrix A = tridiagonal(n, 0.05);
  const Vector b = Random(403).uniform_vector(n, -1.0, 1.0);
  const auto identity = [](const double* r, double* z) { std::copy(r, r + n, z); };
  Gmres gmres;
  Vector x = Vector::Zero(n);
  const KrylovResult patient = gmres.solve(A, b, x, identity, 1e-12 * b.norm(), 30);
  ASSERT_FALSE(patient.converged) << "precondition: 30 iterations are not enough";
  EXPECT_EQ(patient.iterations, 30);
  x.setZero();
  const KrylovResult hasty = gmres.solve(A, b, x, identity, 1e-12 * b.norm(), 30, true);
  EXPECT_FALSE(hasty.converged);
  EXPECT_LE(hasty.iterations, 5);

  // A good preconditioner converges as it would have without give_up_early.
  const SparseMatrix B = tridiagonal(n, 3.0);
  const Eigen::PartialPivLU<Eigen::MatrixXd> factor(Eigen::MatrixXd(tridiagonal(n, 3.1)));
  const auto nearby = [&](const double* r, double* z) {
    Eigen::Map<Vector>(z, n) = factor.solve(Eigen::Map<const Vector>(r, n));
  };
  x.setZero();
  const KrylovResult plain = gmres.solve(B, b, x, nearby, 1e-12 * b.norm(), 30);
  x.setZero();
  const KrylovResult early = gmres.solve(B, b, x, nearby, 1e-12 * b.norm(), 30, true);
  ASSERT_TRUE(plain.converged);
  EXPECT_TRUE(early.converged);
  EXPECT_EQ(early.iterations, plain.iterations);
}

}  // namespace
}  // namespace fosssim::testing
