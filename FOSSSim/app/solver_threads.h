#pragma once
// How many threads the BLAS behind the sparse solvers (MUMPS, CHOLMOD, UMFPACK) may use: a
// setting of the process, which only the program makes (core holds no process-wide state).

namespace fosssim {

/// Sets the threads of OpenBLAS and of OpenMP (which CHOLMOD uses) to `count` (>= 1), before
/// the first solve. The environment (OPENBLAS_NUM_THREADS, OMP_NUM_THREADS) is overridden, so
/// that a run's bytes depend on --threads alone (docs/solvers.md, "Threads and determinism").
/// OpenBLAS's pool, started before main, was already sized from --threads by
/// cli/blas_threads_at_start.cpp; this sets the exact count.
/// Returns false when the BLAS this program was linked with offers no way to set it (a BLAS
/// other than OpenBLAS, which then runs as it was built).
bool set_solver_threads(int count);

}  // namespace fosssim
