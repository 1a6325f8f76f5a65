#pragma once
// Algebraic multigrid for large step matrices: hypre's BoomerAMG, alone as a preconditioner or
// inside hypre's conjugate gradients (docs/solvers.md, "Algebraic multigrid").

#include <memory>

#include "core/solvers/gmres.h"
#include "core/types.h"

namespace fosssim {

/// Whether this build was compiled with hypre's headers (libhypre-dev; FOSSSIM_USE_HYPRE).
/// Loads nothing.
bool amg_built_in();

/// Whether multigrid can run: hypre is built in and its shared library (with OpenMPI) loads.
/// The first call opens the library and starts MPI, or, when that fails, says why once on
/// stderr; call it only when a solve wants multigrid, so that other runs load neither.
/// FOSSSIM_HYPRE_LIBRARY in the environment names another library file to open (a missing one
/// tests the fallback). Without it AmgSolver sets nothing up and StepSolver takes the other paths.
bool amg_available();

/// A BoomerAMG hierarchy (Henson and Yang, "BoomerAMG: a parallel algebraic multigrid solver
/// and preconditioner", Appl. Numer. Math. 41, 2002) of one matrix, used as the preconditioner of
/// a Krylov method: one V-cycle approximates A⁻¹ r at a cost linear in A's entries, and its
/// quality does not degrade as the mesh is refined, so CG or GMRES take about as many
/// iterations at 10⁵ unknowns as at 10³. Unknowns are interleaved by particle (x₀ y₀ x₁ y₁ …):
/// with `components` = dim, coarsening and interpolation treat each coordinate as its own
/// function (the "unknown approach" for systems, as for elasticity).
///
/// Hypre as Debian builds it uses MPI: loading it (amg_available) initialises MPI (a single
/// process, MPI_COMM_SELF) unless the program did, and finalises it at exit.
class AmgSolver {
 public:
  AmgSolver();
  ~AmgSolver();
  AmgSolver(const AmgSolver&) = delete;
  AmgSolver& operator=(const AmgSolver&) = delete;

  /// Builds the hierarchy of A (square, n × n, entries of all rows). false when hypre is not
  /// available or fails (the hierarchy is then unusable).
  bool setup(const SparseMatrix& A, int components);
  /// Makes A (of the size of the last setup's matrix) the matrix conjugate_gradients solves,
  /// keeping the hierarchy of the last setup as its preconditioner: a hierarchy of a nearby
  /// matrix (the previous Newton iteration's or step's) preconditions almost as well and costs
  /// no setup. false when no hierarchy is set up or hypre refuses A.
  bool set_matrix(const SparseMatrix& A);
  /// Whether a hierarchy is set up.
  bool ready() const;
  /// z = one V-cycle from zero on r (the preconditioner M⁻¹ r); r and z of A's size, apart.
  void apply(const double* r, double* z) const;
  /// Conjugate gradients (hypre's PCG, two-norm) on the matrix of the last setup or set_matrix, preconditioned
  /// by its hierarchy, from x (in/out) until ‖b − A x‖ ≤ relative_tolerance ‖b‖ or
  /// max_iterations. Meaningful for a symmetric A; an indefinite one makes it stall or break
  /// down, which the result reports as not converged (the caller checks the residual too).
  KrylovResult conjugate_gradients(const Vector& b, Vector& x, double relative_tolerance,
                                   int max_iterations) const;

 private:
  struct Hypre;
  std::unique_ptr<Hypre> hypre_;
};

}  // namespace fosssim
