#pragma once
// The sparse direct solvers' libraries, loaded on demand: CHOLMOD (Cholesky), UMFPACK (LU) and
// sequential MUMPS (LDLᵀ), with the OpenBLAS, gfortran, METIS and SCOTCH they bring. They are
// not linked: a run that never factors a matrix (explicit integrators, the contest scenes) never
// maps them, and the dynamic loader's start-up work for them (OpenBLAS alone has about 16,000
// symbol relocations) is paid by the first factorization instead (docs/architecture.md,
// "Libraries loaded on demand"). A call to a new function of theirs is one more name in the
// lists below.

#include <cholmod.h>
#include <dmumps_c.h>
#include <smumps_c.h>
#include <umfpack.h>

#include "core/shared_library.h"
#include "core/solvers/solver_library_threads.h"

namespace fosssim {

#define FOSSSIM_CHOLMOD_FUNCTIONS(X)                                                  \
  X(cholmod_analyze)                                                                  \
  X(cholmod_factorize) X(cholmod_finish) X(cholmod_free_dense) X(cholmod_free_factor) \
      X(cholmod_solve2) X(cholmod_start)
#define FOSSSIM_UMFPACK_FUNCTIONS(X)                                           \
  X(umfpack_di_defaults)                                                       \
  X(umfpack_di_free_numeric) X(umfpack_di_free_symbolic) X(umfpack_di_numeric) \
      X(umfpack_di_symbolic) X(umfpack_di_wsolve)

/// The functions of one solver library (core/shared_library.h).
struct CholmodLibrary {
  CholmodLibrary();
  SharedLibrary library;
  FOSSSIM_CHOLMOD_FUNCTIONS(FOSSSIM_LIBRARY_FUNCTION)
};
struct UmfpackLibrary {
  UmfpackLibrary();
  SharedLibrary library;
  FOSSSIM_UMFPACK_FUNCTIONS(FOSSSIM_LIBRARY_FUNCTION)
};
struct MumpsLibrary {  // double and single precision: two libraries
  MumpsLibrary();
  SharedLibrary double_library, single_library;
  decltype(&::dmumps_c) dmumps_c = double_library.symbol<decltype(&::dmumps_c)>("dmumps_c");
  decltype(&::smumps_c) smumps_c = single_library.symbol<decltype(&::smumps_c)>("smumps_c");
};

/// Each library, loaded (with dlopen) the first time it is asked for and kept until the
/// process ends. A library that cannot be loaded throws Error (ErrorKind::kUnavailable, exit 2)
/// naming it and the Debian package that has it; the next call tries again.
const CholmodLibrary& cholmod_library();
const UmfpackLibrary& umfpack_library();
const MumpsLibrary& mumps_library();

}  // namespace fosssim
