#pragma once
// Solves the implicit step systems A x = b: the one interface to the sparse solvers.

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/solvers/cholesky_factor.h"
#include "core/solvers/gmres.h"
#include "core/types.h"

namespace fosssim {

/// Which library solves the step systems (the option "solver" of the implicit integrators).
enum class SolverChoice {
  kAuto,     ///< Eigen below StepSolver::kCholmodFromSize unknowns, CHOLMOD from there on
  kEigen,    ///< Eigen's sparse LDLᵀ and LU, factored at every solve
  kCholmod,  ///< CHOLMOD's Cholesky factor, reused through GMRES while it pays
};

/// What solved the last system.
enum class Factorization {
  kLDLT,      ///< Eigen's LDLᵀ of A
  kLU,        ///< Eigen's LU of A
  kCholesky,  ///< GMRES on A with a CHOLMOD factor of A or of a matrix near it
};

/// Counts of the work done so far, for tests and benchmarks.
struct SolveStatistics {
  std::int64_t solves = 0;
  std::int64_t factorizations = 0;      ///< numeric factorizations (any library)
  std::int64_t analyses = 0;            ///< symbolic analyses (new patterns)
  std::int64_t krylov_iterations = 0;   ///< GMRES iterations over all solves
  std::int64_t definite_fallbacks = 0;  ///< factors of the definite matrix instead of A's
  std::int64_t direct_fallbacks = 0;    ///< CHOLMOD could not help: Eigen's LU or LDLᵀ did
};

/// Solves the systems A x = b of an implicit integrator: one step matrix
/// A = M + h² hessX + h hessV after another, all of one sparsity pattern, with values that
/// change a little between Newton iterations and steps. Every answer it returns has a
/// residual at round-off level, ‖A x - b‖ ≤ 1e-12 (‖b‖ + ‖A‖_F ‖x‖), whichever path made it.
///
/// Two paths, chosen by SolverChoice and the size of A:
/// - Eigen (small systems, and the path of the course's small scenes, bit for bit): a
///   symmetric A is factored by Eigen's SimplicialLDLT, accepted only at round-off residual
///   (a compressed spring or Newtonian gravity can make A indefinite, where LDLᵀ without
///   pivoting may lose accuracy); otherwise, and as the fallback, sparse LU with partial
///   pivoting (correct for the non-symmetric A of damped springs and vortices). The symbolic
///   analysis is reused while the pattern stays the same; the numbers are factored every solve.
/// - CHOLMOD (large systems): a Cholesky factor of a symmetric positive definite matrix near A
///   preconditions GMRES on A itself. The matrix factored is A when A is symmetric positive
///   definite, its symmetric part (A + Aᵀ)/2 for damped springs and vortices, and otherwise the
///   caller's `definite` matrix (the step matrix with projected spring Hessians). The factor
///   is kept across solves, Newton iterations and steps while GMRES converges fast with it:
///   the iterations beyond those a fresh factor needs are charged at their cost, and A is
///   factored again once they have cost as much as a factorization (a rent-or-buy rule, so
///   that a run never pays more than twice what the best choice of refactorizations would).
///   The cost model counts operations, never clocks, so the same input gives the same bits.
///   The symbolic analysis (ordering, supernodes) is done once per pattern.
class StepSolver {
 public:
  /// Systems of at least this many unknowns go to CHOLMOD under SolverChoice::kAuto (measured
  /// with bench_implicit: below it Eigen's simplicial factorization is as fast, and the course's
  /// scenes keep their exact trajectories).
  static constexpr int kCholmodFromSize = 1000;

  /// A symmetric positive definite matrix of A's pattern close to A, asked for only when
  /// neither A nor its symmetric part is positive definite.
  using DefiniteMatrix = std::function<const SparseMatrix&()>;

  /// symmetric: whether A is known to be symmetric (SceneModel::has_symmetric_jacobians).
  explicit StepSolver(bool symmetric, SolverChoice choice = SolverChoice::kAuto)
      : symmetric_(symmetric), choice_(choice) {}

  /// Returns x with A x = b, or nullopt when A is numerically singular.
  std::optional<Vector> solve(const SparseMatrix& A, const Vector& b,
                              const DefiniteMatrix& definite = {});

  /// What solved the last system.
  Factorization last_factorization() const { return last_; }
  const SolveStatistics& statistics() const { return statistics_; }
  /// The CHOLMOD factor (for its size and layout), or nullptr on the Eigen path.
  const CholeskyFactor* cholesky() const { return cholesky_ ? &*cholesky_ : nullptr; }

 private:
  bool same_pattern(const SparseMatrix& A) const;
  void take_pattern(const SparseMatrix& A);
  bool use_cholmod(const SparseMatrix& A) const;
  std::optional<Vector> solve_eigen(const SparseMatrix& A, const Vector& b);
  std::optional<Vector> solve_ldlt(const SparseMatrix& A, const Vector& b);
  std::optional<Vector> solve_lu(const SparseMatrix& A, const Vector& b);
  std::optional<Vector> solve_cholmod(const SparseMatrix& A, const Vector& b,
                                      const DefiniteMatrix& definite);
  /// Factors the matrix GMRES is preconditioned with, for A; false when none could be.
  bool refactor(const SparseMatrix& A, const DefiniteMatrix& definite);
  /// preconditioner_ = (M + Mᵀ)/2 over M's pattern (which is A's).
  void symmetrize(const SparseMatrix& M);

  bool symmetric_;
  SolverChoice choice_;
  Factorization last_ = Factorization::kLU;
  SolveStatistics statistics_;
  std::vector<SparseMatrix::StorageIndex> outer_, inner_;  // pattern of the analysed matrix

  // The Eigen path.
  bool ldlt_analysed_ = false;
  bool lu_analysed_ = false;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;

  // The CHOLMOD path.
  std::optional<CholeskyFactor> cholesky_;
  bool structurally_symmetric_ = false;
  std::vector<int> transposed_;  // slot of entry (j, i) for the entry (i, j) in slot k
  SparseMatrix preconditioner_;  // the matrix factored, when it is not A itself
  Gmres gmres_;
  bool refactor_due_ = true;
  double factor_cost_ = 0.0;     // of one factorization, in operations
  double iteration_cost_ = 0.0;  // of one GMRES iteration, in operations
  double charged_ = 0.0;         // cost of the iterations beyond a fresh factor's, since it
  int fresh_iterations_ = 0;     // GMRES iterations of the first solve after a factorization
  bool first_after_factor_ = false;
  Vector work_;
};

}  // namespace fosssim
