#include "app/solver_threads.h"

// OpenBLAS and libgomp come in through SuiteSparse and MUMPS, not linked by us directly; weak
// declarations find them when they are loaded and are null otherwise (another BLAS).
extern "C" {
void openblas_set_num_threads(int count) __attribute__((weak));
void omp_set_num_threads(int count) __attribute__((weak));
}

namespace fosssim {

bool set_solver_threads(int count) {
  if (omp_set_num_threads != nullptr) omp_set_num_threads(count);
  if (openblas_set_num_threads == nullptr) return false;
  openblas_set_num_threads(count);
  return true;
}

}  // namespace fosssim
