#pragma once
// The thread count of the libraries behind the sparse direct solvers (OpenBLAS, OpenMP), without
// their headers (core/solvers/solver_libraries.h loads them).

namespace fosssim {

/// The number of threads (>= 1) the BLAS and OpenMP behind these libraries start with and
/// use, set by the program from --threads before the first factorization
/// (app/solver_threads.cpp). OpenBLAS starts its thread pool when it is loaded, as many threads
/// as the CPUs the loading thread may run on: the first load is made with the calling thread
/// narrowed to `count` CPUs (given back right after), then openblas_set_num_threads and
/// omp_set_num_threads set the exact count. When the libraries are already loaded, the count
/// is set at once. Never called (tests, the Python module): the BLAS starts as it decides
/// (OPENBLAS_NUM_THREADS, else every CPU).
void set_solver_library_threads(int count);

}  // namespace fosssim
