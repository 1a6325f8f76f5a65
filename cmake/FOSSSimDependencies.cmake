# The libraries FOSSSim links that have no CMake package files on Debian, as imported targets:
# SuiteSparse::CHOLMOD, SuiteSparse::UMFPACK and MUMPS::mumps. Included by the build and by the
# installed package (FOSSSimConfig.cmake), so that a project linking FOSSSim's static libraries
# finds them the same way; each target is made only once.

if(NOT TARGET SuiteSparse::CHOLMOD)
  # SuiteSparse's CHOLMOD (sparse Cholesky) and UMFPACK (sparse LU), which bring the BLAS Debian
  # selects (OpenBLAS, threaded, from libopenblas-dev). Debian's libsuitesparse-dev has no CMake
  # package files.
  find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
  find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
  find_library(UMFPACK_LIBRARY umfpack REQUIRED)
  add_library(SuiteSparse::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES IMPORTED_LOCATION ${CHOLMOD_LIBRARY}
                        INTERFACE_INCLUDE_DIRECTORIES ${CHOLMOD_INCLUDE_DIR})
  add_library(SuiteSparse::UMFPACK UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::UMFPACK PROPERTIES IMPORTED_LOCATION ${UMFPACK_LIBRARY}
                        INTERFACE_INCLUDE_DIRECTORIES ${CHOLMOD_INCLUDE_DIR})
  # MUMPS, sequential (libmumps-seq-dev): the symmetric indefinite factorization of step
  # matrices, in double and in single precision. Debian installs its headers in the default path, the sequential MPI stubs it
  # needs in mumps_seq/.
  find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
  find_path(MUMPS_SEQ_MPI_INCLUDE_DIR mpi.h PATHS /usr/include/mumps_seq NO_DEFAULT_PATH REQUIRED)
  find_library(DMUMPS_LIBRARY dmumps_seq REQUIRED)
  find_library(SMUMPS_LIBRARY smumps_seq REQUIRED)
  find_library(MUMPS_COMMON_LIBRARY mumps_common_seq REQUIRED)
  find_library(MUMPS_MPISEQ_LIBRARY mpiseq_seq REQUIRED)
  add_library(MUMPS::mumps INTERFACE IMPORTED)
  set_target_properties(MUMPS::mumps PROPERTIES
                        INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR};${MUMPS_SEQ_MPI_INCLUDE_DIR}"
                        INTERFACE_LINK_LIBRARIES
                        "${DMUMPS_LIBRARY};${SMUMPS_LIBRARY};${MUMPS_COMMON_LIBRARY};${MUMPS_MPISEQ_LIBRARY}")
endif()

# The soname of each solver library (what the build links against; FOSSSim loads them with
# dlopen by these names: FOSSSim/core/solvers/solver_libraries.h).
foreach(solver_library CHOLMOD UMFPACK DMUMPS SMUMPS)
  if(NOT ${solver_library}_SONAME AND ${solver_library}_LIBRARY)
    execute_process(COMMAND ${CMAKE_OBJDUMP} -p ${${solver_library}_LIBRARY}
                    OUTPUT_VARIABLE solver_library_dump ERROR_QUIET)
    if(NOT solver_library_dump MATCHES "SONAME +([^ \n]+)")
      message(FATAL_ERROR "no soname found in ${${solver_library}_LIBRARY} (objdump -p)")
    endif()
    set(${solver_library}_SONAME ${CMAKE_MATCH_1} CACHE STRING "soname of ${solver_library}")
  endif()
endforeach()

if(NOT TARGET ODE::lcp)
  # ODE's LCP solver (Dantzig's method), as Debian packages it with DART
  # (libdart-external-odelcpsolver-dev): rigid-body contact (FOSSSim/core/rigid/contact_lcp.h).
  # libode-dev does not export its LCP solver.
  find_path(ODE_LCP_INCLUDE_DIR dart/external/odelcpsolver/lcp.h REQUIRED)
  find_library(ODE_LCP_LIBRARY dart-external-odelcpsolver REQUIRED)
  add_library(ODE::lcp UNKNOWN IMPORTED)
  set_target_properties(ODE::lcp PROPERTIES IMPORTED_LOCATION ${ODE_LCP_LIBRARY}
                        INTERFACE_INCLUDE_DIRECTORIES ${ODE_LCP_INCLUDE_DIR})
endif()

# Optional: hypre's BoomerAMG (libhypre-dev), the algebraic multigrid of large step matrices
# (core/solvers/amg_solver.h). Only its headers and OpenMPI's (Debian builds hypre with OpenMPI)
# are used at build time: FOSSSim does not link hypre but opens it with dlopen when a step asks
# for multigrid, so that other runs load neither (FOSSSim/CMakeLists.txt). Sets
# FOSSSIM_HYPRE_INCLUDE_DIRS and FOSSSIM_HYPRE_SONAME (the file name to open) when found; left out
# when FOSSSIM_USE_HYPRE is OFF (the browser build) or anything is missing, and solver="amg" then
# takes the sparse direct path.
if(NOT DEFINED FOSSSIM_HYPRE_SONAME AND (NOT DEFINED FOSSSIM_USE_HYPRE OR FOSSSIM_USE_HYPRE))
  find_path(HYPRE_INCLUDE_DIR HYPRE_parcsr_ls.h PATH_SUFFIXES hypre)
  find_library(HYPRE_LIBRARY HYPRE)
  find_package(MPI QUIET COMPONENTS CXX)
  if(HYPRE_INCLUDE_DIR AND HYPRE_LIBRARY AND MPI_CXX_FOUND)
    # Debian's libHYPRE.so links to the versioned file, whose name is the library's soname, the
    # name the run-time package (libhypre-2.26.0) provides.
    file(REAL_PATH "${HYPRE_LIBRARY}" _fosssim_hypre_file)
    get_filename_component(FOSSSIM_HYPRE_SONAME "${_fosssim_hypre_file}" NAME)
    set(FOSSSIM_HYPRE_INCLUDE_DIRS ${HYPRE_INCLUDE_DIR} ${MPI_CXX_INCLUDE_DIRS})
  endif()
endif()
