#pragma once
// How many threads the BLAS behind the sparse solvers (MUMPS, CHOLMOD, UMFPACK) may use: a
// setting of the process, which only the program makes (core holds no process-wide state).

namespace fosssim {

/// Sets the threads of OpenBLAS and of OpenMP (which CHOLMOD uses) to `count` (>= 1), before
/// the first solve. The environment (OPENBLAS_NUM_THREADS, OMP_NUM_THREADS) is overridden, so
/// that a run's bytes depend on --threads alone (docs/solvers.md, "Threads and determinism").
/// The solvers' libraries are loaded by the first factorization (core/solvers/solver_libraries.h):
/// OpenBLAS's pool then starts with at most `count` threads and the exact count is set.
/// Returns true: a BLAS other than OpenBLAS, which offers no way to set it, is only seen when
/// loaded, and then runs as it was built.
bool set_solver_threads(int count);

}  // namespace fosssim
