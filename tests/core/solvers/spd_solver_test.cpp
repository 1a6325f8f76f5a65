// SpdSolver: one factorization, many solves of several columns at once.

#include "core/solvers/spd_solver.h"

#include <gtest/gtest.h>

#include <random>

namespace fosssim {
namespace {

/// A random sparse SPD matrix: a graph Laplacian plus a positive diagonal.
SparseMatrix random_spd(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> node(0, n - 1);
  std::uniform_real_distribution<double> weight(0.1, 10.0);
  std::vector<Triplet> t;
  for (int e = 0; e < 3 * n; ++e) {
    const int a = node(rng), b = node(rng);
    if (a == b) continue;
    const double w = weight(rng);
    t.emplace_back(a, a, w);
    t.emplace_back(b, b, w);
    t.emplace_back(a, b, -w);
    t.emplace_back(b, a, -w);
  }
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, weight(rng));
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

TEST(SpdSolver, SparseAndDenseSolveAllColumnsAccurately) {
  const SparseMatrix A = random_spd(200, 3);
  const Points<3> B = Points<3>::Random(200, 3);
  for (auto method : {SpdSolver::Method::kSparse, SpdSolver::Method::kDense}) {
    SpdSolver solver;
    ASSERT_TRUE(solver.factor(A, method));
    Points<3> X = B;
    solver.solve_in_place<3>(X);
    EXPECT_LT((A * Eigen::MatrixXd(X) - Eigen::MatrixXd(B)).norm(), 1e-12 * B.norm());
  }
}

TEST(SpdSolver, RefactorReusesTheAnalysisForNewValues) {
  SparseMatrix A = random_spd(50, 7);
  SpdSolver solver;
  ASSERT_TRUE(solver.factor(A, SpdSolver::Method::kSparse));
  for (int i = 0; i < 50; i += 5) A.coeffRef(i, i) += 100.0;  // a stiffer diagonal, same pattern
  ASSERT_TRUE(solver.refactor(A));
  Points<2> X = Points<2>::Ones(50, 2);
  solver.solve_in_place<2>(X);
  EXPECT_LT((A * Eigen::MatrixXd(X) - Eigen::MatrixXd::Ones(50, 2)).norm(), 1e-12);
  EXPECT_GT(solver.factor_nonzeros(), 50);
}

TEST(SpdSolver, RejectsAnIndefiniteMatrix) {
  SparseMatrix A(2, 2);
  A.insert(0, 0) = 1.0;
  A.insert(1, 1) = -1.0;
  SpdSolver solver;
  EXPECT_FALSE(solver.factor(A, SpdSolver::Method::kSparse));
  EXPECT_FALSE(solver.factor(A, SpdSolver::Method::kDense));
}

}  // namespace
}  // namespace fosssim
