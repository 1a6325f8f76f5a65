// Tests of StepSolver's multigrid path (SolverChoice::kAmg: hypre's BoomerAMG preconditioning
// conjugate gradients or GMRES, core/solvers/amg_solver.h). Skipped in builds without hypre.
//
// Math checked, on step matrices A = M + h² hessX + h hessV of a 2D spring grid (particles on
// a jittered square lattice, springs along the edges and both diagonals, the left column fixed,
// so A has identity rows and columns for the fixed unknowns):
// - stretched springs (l0 = l/2) give a symmetric positive definite A: CG answers meet the
//   promise ‖A x − b‖ ≤ 1e-12 (‖b‖ + ‖A‖_F ‖x‖), and agree with the sparse direct path's answer
//   to the conditioning bound ‖x − x_direct‖ ≤ ‖A⁻¹‖₂ (‖r‖ + ‖r_direct‖);
// - damped springs give a non-symmetric A: GMRES answers meet the same promise and bound;
// - strongly compressed springs (l0 = 3 l) at a large step give a symmetric indefinite A
//   (checked by its eigenvalues): multigrid CG does not reach the residual, the failure is
//   counted, the sparse direct path answers to the promise, and the next solve skips multigrid;
// - the same input gives the same bits; under kAuto small systems never set multigrid up.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "core/force_set.h"
#include "core/solvers/amg_solver.h"
#include "core/solvers/step_solver.h"
#include "core/systems/step_matrix.h"
#include "support/random.h"
#include "support/scene_builder.h"

namespace fosssim::testing {
namespace {

/// The step matrix of an nx × nx spring grid in 2D (spacing 1/nx, jittered by a tenth of it),
/// springs of stiffness k with rest length l0_factor × their initial length and damping b.
SparseMatrix grid_step_matrix(int nx, double l0_factor, double b, double h, unsigned seed) {
  Random random(seed);
  TestScene scene(2);
  const double spacing = 1.0 / nx;
  for (int r = 0; r < nx; ++r) {
    for (int c = 0; c < nx; ++c) {
      Vector x(2);
      x << c * spacing + random.uniform(-0.1, 0.1) * spacing,
          r * spacing + random.uniform(-0.1, 0.1) * spacing;
      scene.add_particle(1.0 / (nx * nx), x, random.uniform_vector(2, -0.1, 0.1), c == 0);
    }
  }
  const auto spring = [&](int i, int j) {
    const double l = (scene.initial.q.segment(2 * i, 2) - scene.initial.q.segment(2 * j, 2)).norm();
    scene.add_spring(i, j, 100.0, l0_factor * l, b);
  };
  for (int r = 0; r < nx; ++r) {
    for (int c = 0; c < nx; ++c) {
      const int p = r * nx + c;
      if (c + 1 < nx) spring(p, p + 1);
      if (r + 1 < nx) spring(p, p + nx);
      if (c + 1 < nx && r + 1 < nx) spring(p, p + nx + 1);
      if (c > 0 && r + 1 < nx) spring(p, p + nx - 1);
    }
  }
  const ForceSet forces(scene.model);
  StepMatrix matrix(forces, FixedParticleRule::kIdentityRows);
  return matrix.assemble(scene.initial.q, scene.initial.v, h);
}

double promise(const SparseMatrix& A, const Vector& x, const Vector& b) {
  return 1e-12 * (b.norm() + A.norm() * x.norm());
}

/// Expects x (from multigrid) to meet the residual promise and to agree with the sparse direct
/// path's answer to the conditioning bound.
void expect_agrees_with_direct(const SparseMatrix& A, const Vector& x, const Vector& b,
                               bool symmetric) {
  const double residual = (A * x - b).norm();
  EXPECT_LE(residual, promise(A, x, b));
  StepSolver direct(symmetric, SolverChoice::kSparseDirect, 2);
  const auto reference = direct.solve(A, b);
  ASSERT_TRUE(reference.has_value());
  const double reference_residual = (A * *reference - b).norm();
  EXPECT_LE(reference_residual, promise(A, *reference, b));
  const double inverse_norm =
      1.0 / Eigen::BDCSVD<Eigen::MatrixXd>(Eigen::MatrixXd(A)).singularValues().minCoeff();
  EXPECT_LE((x - *reference).norm(), inverse_norm * (residual + reference_residual));
  std::printf("multigrid vs direct: |x - x_direct| = %.2e, bound %.2e, residual %.2e (promise "
              "%.2e)\n",
              (x - *reference).norm(), inverse_norm * (residual + reference_residual), residual,
              promise(A, x, b));
}

class AmgStepSolver : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!amg_available()) GTEST_SKIP() << "hypre is not built in or cannot be loaded";
  }
};

TEST_F(AmgStepSolver, SolvesSymmetricPositiveDefiniteStepMatricesByCgToThePromise) {
  const SparseMatrix A = grid_step_matrix(16, 0.5, 0.0, 0.1, 301);
  ASSERT_EQ(Eigen::MatrixXd(A).llt().info(), Eigen::Success) << "precondition: A is SPD";
  const Vector b = Random(302).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
  StepSolver solver(true, SolverChoice::kAmg, 2);
  const auto x = solver.solve(A, b);
  ASSERT_TRUE(x.has_value());
  EXPECT_EQ(solver.last_factorization(), Factorization::kAmgCg);
  EXPECT_EQ(solver.statistics().amg_setups, 1);
  EXPECT_EQ(solver.statistics().amg_failures, 0);
  EXPECT_EQ(solver.statistics().factorizations, 0);
  EXPECT_GT(solver.statistics().krylov_iterations, 0);
  expect_agrees_with_direct(A, *x, b, true);

  // A second system of the same pattern (another step): a new hierarchy, the same promise.
  const SparseMatrix A2 = grid_step_matrix(16, 0.5, 0.0, 0.2, 301);
  const auto x2 = solver.solve(A2, b);
  ASSERT_TRUE(x2.has_value());
  EXPECT_EQ(solver.last_factorization(), Factorization::kAmgCg);
  expect_agrees_with_direct(A2, *x2, b, true);
}

TEST_F(AmgStepSolver, SolvesNonSymmetricStepMatricesByGmresToThePromise) {
  const SparseMatrix A = grid_step_matrix(16, 0.5, 0.5, 0.1, 303);
  ASSERT_GT((Eigen::MatrixXd(A) - Eigen::MatrixXd(A).transpose()).norm(), 1e-3)
      << "precondition: A is not symmetric";
  const Vector b = Random(304).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
  StepSolver solver(false, SolverChoice::kAmg, 2);
  const auto x = solver.solve(A, b);
  ASSERT_TRUE(x.has_value());
  EXPECT_EQ(solver.last_factorization(), Factorization::kAmgGmres);
  EXPECT_EQ(solver.statistics().amg_failures, 0);
  expect_agrees_with_direct(A, *x, b, false);
}

// Multigrid's point (docs/solvers.md, "Algebraic multigrid"): the iterations a solve takes do not
// grow as the mesh is refined, so a step's cost grows with its unknowns. Damped grids of 4 and
// 16 times the particles of the smallest: every fresh solve meets the promise in at most 25
// GMRES iterations (15 to 17 on bench_elastic's cloths), and the finest grid takes at most 3
// more than the coarsest. (Without a working hierarchy, e.g. one level of smoothing only, the
// iterations grow with the grid's width.)
TEST_F(AmgStepSolver, IterationsDoNotGrowWithTheGrid) {
  std::vector<std::int64_t> iterations;
  for (const int nx : {24, 48, 96}) {
    const SparseMatrix A = grid_step_matrix(nx, 0.5, 0.5, 0.1, 313);
    const Vector b = Random(314).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
    StepSolver solver(false, SolverChoice::kAmg, 2);
    const auto x = solver.solve(A, b);
    ASSERT_TRUE(x.has_value()) << nx;
    EXPECT_EQ(solver.last_factorization(), Factorization::kAmgGmres) << nx;
    EXPECT_LE((A * *x - b).norm(), promise(A, *x, b)) << nx;
    iterations.push_back(solver.statistics().krylov_iterations);
    std::printf("%d x %d grid, %d unknowns: %lld GMRES iterations\n", nx, nx,
                static_cast<int>(A.rows()), static_cast<long long>(iterations.back()));
    EXPECT_LE(iterations.back(), 25) << nx;
  }
  EXPECT_LE(iterations.back(), iterations.front() + 3);
}

TEST_F(AmgStepSolver, IndefiniteMatricesFallBackToTheDirectPathNeverAWrongAnswer) {
  const SparseMatrix A = grid_step_matrix(16, 3.0, 0.0, 1.0, 305);
  const auto eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues();
  ASSERT_LT(eigenvalues.minCoeff(), 0.0) << "precondition: A is indefinite";
  int negative = 0;
  for (const double e : eigenvalues) negative += e < 0.0;
  const Vector b = Random(306).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
  StepSolver solver(true, SolverChoice::kAmg, 2);
  const auto x = solver.solve(A, b);
  ASSERT_TRUE(x.has_value());
  std::printf("indefinite A (%d of %d eigenvalues negative, %.3g .. %.3g): multigrid CG took %lld "
              "iterations and missed the residual; solved by factorization %d\n",
              negative, static_cast<int>(A.rows()), eigenvalues.minCoeff(), eigenvalues.maxCoeff(),
              static_cast<long long>(solver.statistics().krylov_iterations),
              static_cast<int>(solver.last_factorization()));
  EXPECT_EQ(solver.statistics().amg_failures, 1);
  EXPECT_NE(solver.last_factorization(), Factorization::kAmgCg);
  EXPECT_LE((A * *x - b).norm(), promise(A, *x, b));

  // The next solve goes to the direct path at once (no second hierarchy).
  const auto again = solver.solve(A, b);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(solver.statistics().amg_setups, 1);
  EXPECT_LE((A * *again - b).norm(), promise(A, *again, b));
}

TEST_F(AmgStepSolver, GivesTheSameBitsFromRunToRun) {
  const SparseMatrix A = grid_step_matrix(12, 0.5, 0.5, 0.1, 307);
  const Vector b = Random(308).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
  for (const bool symmetric : {true, false}) {
    const SparseMatrix M = symmetric ? grid_step_matrix(12, 0.5, 0.0, 0.1, 307) : A;
    StepSolver first(symmetric, SolverChoice::kAmg, 2), second(symmetric, SolverChoice::kAmg, 2);
    const auto x1 = first.solve(M, b);
    const auto x2 = second.solve(M, b);
    ASSERT_TRUE(x1 && x2);
    EXPECT_EQ(*x1, *x2);
  }
}

TEST_F(AmgStepSolver, AutoSetsUpNoMultigridForSmallSystems) {
  const SparseMatrix A = grid_step_matrix(8, 0.5, 0.0, 0.1, 309);
  ASSERT_LT(A.rows(), StepSolver::kAmgFromSize);  // and A is symmetric: never under kAuto
  const Vector b = Random(310).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
  StepSolver solver(true, SolverChoice::kAuto, 2);
  ASSERT_TRUE(solver.solve(A, b).has_value());
  EXPECT_EQ(solver.statistics().amg_setups, 0);
}

// The rule of kAuto (docs/solvers.md): non-symmetric systems take multigrid from kAmgFromSize
// unknowns, the sparse direct path below; symmetric ones never. Grids just below and just above
// the threshold, damped (non-symmetric) and undamped (symmetric); every answer meets the promise.
TEST_F(AmgStepSolver, AutoTakesMultigridForNonSymmetricSystemsFromTheThresholdOnly) {
  const int above = static_cast<int>(std::ceil(std::sqrt(StepSolver::kAmgFromSize / 2.0)));
  struct Case {
    int nx;
    double damping;
    bool multigrid;
  };
  for (const Case c : {Case{above - 1, 0.5, false}, Case{above, 0.5, true}, Case{above, 0.0, false}}) {
    const bool symmetric = c.damping == 0.0;
    const SparseMatrix A = grid_step_matrix(c.nx, 0.5, c.damping, 0.1, 311);
    ASSERT_EQ(A.rows() >= StepSolver::kAmgFromSize, c.nx == above) << c.nx;
    const Vector b = Random(312).uniform_vector(static_cast<int>(A.rows()), -1.0, 1.0);
    StepSolver solver(symmetric, SolverChoice::kAuto, 2);
    const auto x = solver.solve(A, b);
    ASSERT_TRUE(x.has_value()) << c.nx;
    EXPECT_LE((A * *x - b).norm(), promise(A, *x, b)) << c.nx;
    EXPECT_EQ(solver.statistics().amg_setups, c.multigrid ? 1 : 0) << c.nx << " " << c.damping;
    EXPECT_EQ(solver.last_factorization() == Factorization::kAmgGmres, c.multigrid) << c.nx;
  }
}

}  // namespace
}  // namespace fosssim::testing
