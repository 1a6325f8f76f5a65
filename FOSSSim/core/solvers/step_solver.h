#pragma once
// Solves the implicit step systems A x = b: the one interface to the sparse solvers.

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/solvers/amg_solver.h"
#include "core/solvers/cholesky_factor.h"
#include "core/solvers/course_lu.h"
#include "core/solvers/gmres.h"
#include "core/solvers/ldlt_factor.h"
#include "core/solvers/lu_factor.h"
#include "core/solvers/symmetric_part.h"
#include "core/types.h"

namespace fosssim {

/// Which library solves the step systems (the option "solver" of the implicit integrators).
enum class SolverChoice {
  kAuto,   ///< the course's dense LU for 2D systems of at most kCourseLuMaxUnknowns unknowns
           ///< (integrators ask uses_course_lu), Eigen below StepSolver::kSparseDirectFromSize
           ///< unknowns, the sparse direct libraries from there on
  kEigen,  ///< Eigen's sparse LDLᵀ and LU, factored at every solve
  kSparseDirect,  ///< sparse direct libraries (MUMPS, CHOLMOD, UMFPACK), reused through GMRES
  kAmg,  ///< a Krylov method preconditioned by algebraic multigrid (hypre's BoomerAMG), with
         ///< the sparse direct libraries (Eigen's below 1000 unknowns) as the fallback
};

/// Whether an implicit integrator solves its step systems the course's way, with a dense
/// StepMatrix::assemble_course and CourseLu, bit for bit the course's results: under kAuto, for
/// 2D systems of at most kCourseLuMaxUnknowns unknowns (course_lu.h).
inline bool uses_course_lu(SolverChoice choice, int dim, int unknowns) {
  return choice == SolverChoice::kAuto && dim == 2 && unknowns <= kCourseLuMaxUnknowns;
}

/// What solved the last system.
enum class Factorization {
  kLDLT,      ///< Eigen's LDLᵀ of A
  kLU,        ///< Eigen's LU of A
  kCholesky,  ///< GMRES on A with a CHOLMOD Cholesky factor of A (or of a nearby matrix)
  kUmfpack,   ///< GMRES on A with an UMFPACK LU factor of A (or of a nearby matrix)
  kMumps,     ///< GMRES on A with a MUMPS LDLᵀ factor of A (or of a nearby matrix)
  kAmgCg,     ///< conjugate gradients on A preconditioned by BoomerAMG (A symmetric)
  kAmgGmres,  ///< GMRES on A preconditioned by BoomerAMG (A non-symmetric)
};

/// Counts of the work done so far, for tests and benchmarks.
struct SolveStatistics {
  std::int64_t solves = 0;
  std::int64_t factorizations = 0;       ///< numeric factorizations (any library), tried or done
  std::int64_t analyses = 0;             ///< symbolic analyses (new patterns)
  std::int64_t krylov_iterations = 0;    ///< GMRES iterations over all solves
  std::int64_t lu_factorizations = 0;    ///< of them, UMFPACK's (after a failed Cholesky)
  std::int64_t ldlt_factorizations = 0;  ///< of them, MUMPS's (A symmetric)
  std::int64_t single_precision_factorizations = 0;  ///< of MUMPS's, in single precision
  std::int64_t direct_fallbacks = 0;  ///< GMRES did not converge: Eigen's LU or LDLᵀ solved
  std::int64_t amg_setups = 0;        ///< BoomerAMG hierarchies built
  std::int64_t amg_failures = 0;  ///< multigrid solves that missed the residual: another path solved
};

/// Solves the systems A x = b of an implicit integrator: one step matrix
/// A = M + h² hessX + h hessV after another, all of one sparsity pattern, with values that
/// change a little between Newton iterations and steps. Every answer it returns has a
/// residual at round-off level, ‖A x - b‖ ≤ 1e-12 (‖b‖ + ‖A‖_F ‖x‖), whichever path made it.
///
/// Three paths, chosen by SolverChoice and the size of A:
/// - Eigen (small systems, and the course's small scenes bit for bit): a symmetric A is
///   factored by Eigen's SimplicialLDLT, accepted only at round-off residual (a compressed
///   spring or Newtonian gravity can make A indefinite, where LDLᵀ without pivoting may lose
///   accuracy); otherwise, and as the fallback, sparse LU with partial pivoting (correct for
///   the non-symmetric A of damped springs and vortices). The symbolic analysis is reused
///   while the pattern stays the same; the numbers are factored at every solve.
/// - Sparse direct libraries (large systems): GMRES on A itself, preconditioned by a factor of
///   an earlier step matrix or of this one. A symmetric A, positive definite or not (a
///   compressed spring makes it indefinite), is factored L D Lᵀ by MUMPS; a non-symmetric one
///   (damping, vortices) by CHOLMOD's supernodal Cholesky of its symmetric part, or by
///   UMFPACK's LU of A when that part is not positive definite or does not precondition well
///   (after Cholesky fails, the next few factorizations go straight to LU). MUMPS factors in
///   single precision (half the time), GMRES in double brings the answer to round-off; when a
///   fresh single-precision factor cannot (A too ill-conditioned for float) or A is singular in
///   float, the pattern's factors are double from then on. The factor is kept
///   across solves, Newton iterations and steps while GMRES converges fast with it: the iterations
///   beyond those a fresh factor needs are charged at their cost, and A is factored again once they
///   have cost as much as a factorization (a rent-or-buy rule: a run never pays more than about
///   twice what the best choice of refactorizations would). When a kept factor fails (the matrices
///   change too much between solves, as for a cloth falling at h = 1/30 s), the next 1, 2, 4, ...
///   16 solves factor at once without trying it. The cost model counts operations, never clocks, so
///   the same input gives the same bits. Each library's symbolic analysis is done once per pattern.
/// - Algebraic multigrid (SolverChoice::kAmg, and kAuto for non-symmetric A from kAmgFromSize
///   unknowns when hypre can be loaded): a BoomerAMG hierarchy of A, kept across solves while it preconditions well (the
///   rent-or-buy rule of the factors, in iterations), preconditions conjugate gradients (A
///   symmetric) or GMRES (A non-symmetric) to the same residual. An indefinite A
///   (compressed elements) can keep them from converging: iterations are bounded, the residual
///   is checked, and a solve that misses it is done by the path above instead (Eigen's below
///   kSparseDirectFromSize unknowns); the next 1, 2, 4, … 16 solves then go there at once.
class StepSolver {
 public:
  /// Systems of at least this many unknowns go to SuiteSparse under SolverChoice::kAuto
  /// (measured with bench_implicit: below it Eigen's simplicial factorizations are as fast,
  /// and the course's scenes keep their exact trajectories).
  static constexpr int kSparseDirectFromSize = 1000;

  /// symmetric: whether A is known to be symmetric (SceneModel::has_symmetric_jacobians).
  /// Non-symmetric systems of at least this many unknowns take algebraic multigrid under
  /// SolverChoice::kAuto when hypre can be loaded; symmetric ones never. Measured with
  /// bench_elastic (docs/solvers.md, "Algebraic multigrid"): on the 2D damped cloth multigrid
  /// costs 1.3× to 1.8× CHOLMOD's path at 2·10⁴ unknowns, 1.39× at 4·10⁴, 0.81× at 8·10⁴ and
  /// 0.63× at 2·10⁵, so the crossover lies between 4·10⁴ and 8·10⁴; on CST sheets (symmetric)
  /// MUMPS's path stays faster up to 10⁵ unknowns.
  static constexpr int kAmgFromSize = 60000;

  /// symmetric: whether A is known to be symmetric (SceneModel::has_symmetric_jacobians).
  /// components: unknowns per particle, interleaved (the dimension), for multigrid's coarsening.
  explicit StepSolver(bool symmetric, SolverChoice choice = SolverChoice::kAuto,
                      int components = 1)
      : symmetric_(symmetric), choice_(choice), components_(components) {}

  /// Returns x with A x = b, or nullopt when A is numerically singular.
  std::optional<Vector> solve(const SparseMatrix& A, const Vector& b);

  /// What solved the last system.
  Factorization last_factorization() const { return last_; }
  const SolveStatistics& statistics() const { return statistics_; }

 private:
  bool same_pattern(const SparseMatrix& A) const;
  void take_pattern(const SparseMatrix& A);
  std::optional<Vector> solve_eigen(const SparseMatrix& A, const Vector& b);
  std::optional<Vector> solve_ldlt(const SparseMatrix& A, const Vector& b);
  std::optional<Vector> solve_lu(const SparseMatrix& A, const Vector& b);
  std::optional<Vector> solve_suitesparse(const SparseMatrix& A, const Vector& b);
  /// nullopt when multigrid is skipped or misses the residual (another path solves then).
  std::optional<Vector> solve_amg(const SparseMatrix& A, const Vector& b);
  /// Factors A (or its symmetric part) for GMRES to precondition with; false when singular.
  bool refactor(const SparseMatrix& A);
  bool factor_cholesky(const SparseMatrix& A);
  bool factor_lu(const SparseMatrix& A);
  bool factor_ldlt(const SparseMatrix& A);
  /// Factors in double precision from now on (for this pattern).
  void use_double_ldlt();
  /// z = M⁻¹ r with the current factor.
  void precondition(const double* r, double* z) const;

  bool symmetric_;
  SolverChoice choice_;
  int components_ = 1;
  Factorization last_ = Factorization::kLU;
  SolveStatistics statistics_;
  std::vector<SparseMatrix::StorageIndex> outer_,
      inner_;  // A's pattern, unless symmetric_part_ has it

  // The Eigen path.
  bool ldlt_analysed_ = false;
  bool lu_analysed_ = false;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;

  // The SuiteSparse path.
  bool suitesparse_ = false;           // the pattern goes to SuiteSparse
  UpperSymmetricPart symmetric_part_;  // of a non-symmetric A, for CHOLMOD
  std::optional<CholeskyFactor> cholesky_;
  std::optional<LuFactor> umfpack_;
  std::optional<LdltFactor> mumps_;
  FactorPrecision ldlt_precision_ = FactorPrecision::kSingle;  // of MUMPS's next factor
  Factorization factor_ = Factorization::kCholesky;            // which one preconditions now
  int skip_cholesky_ = 0;  // factorizations left that go straight to LU
  Gmres gmres_;
  bool refactor_due_ = true;
  double factor_cost_ = 0.0;     // of one factorization, in operations
  double iteration_cost_ = 0.0;  // of one GMRES iteration, in operations
  double charged_ = 0.0;      // cost of the iterations beyond a fresh factor's, since the last one
  int fresh_iterations_ = 0;  // solves with M in the first solve after a factorization
  bool first_after_factor_ = false;
  int backoff_ = 0;           // solves left that factor at once, after a kept factor failed
  int backoff_length_ = 0;    // the next backoff: doubles while kept factors keep failing
  double scale_ratio_ = 0.0;  // ‖A‖ ‖x‖ / ‖b‖ of the last answer

  // The multigrid path.
  bool amg_ = false;  // the pattern goes to BoomerAMG first
  AmgSolver amg_solver_;
  int amg_skip_ = 0;         // solves left that skip multigrid, after one missed
  int amg_skip_length_ = 0;  // the next such run: doubles while multigrid keeps missing
  bool amg_setup_due_ = true;
  int amg_fresh_iterations_ = 0;  // Krylov iterations of the first solve with the hierarchy
  double amg_charged_ = 0.0;      // iterations beyond those, since the hierarchy was set up
};

}  // namespace fosssim
