#include "core/solvers/amg_solver.h"

#if FOSSSIM_HAVE_HYPRE

// Hypre is built against (its headers, and OpenMPI's, which they include) but not linked: the
// library is opened the first time a step asks for multigrid (hypre_api() below), so that runs
// which never do load neither hypre nor OpenMPI. OpenMPI's C++ bindings are not used.
#define OMPI_SKIP_MPICXX 1
#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/shared_library.h"

#ifndef FOSSSIM_HYPRE_LIBRARY
#error "the build names hypre's shared library (FOSSSim/CMakeLists.txt)"
#endif

namespace fosssim {

namespace {

// Every hypre and MPI function FOSSSim calls, resolved once by name from the opened library
// (core/shared_library.h: typed by the headers' declarations, nothing here links).
#define FOSSSIM_HYPRE_FUNCTIONS(X)                                                          \
  X(HYPRE_Init) X(HYPRE_Finalize) X(HYPRE_ClearAllErrors)                                  \
  X(HYPRE_IJMatrixCreate) X(HYPRE_IJMatrixSetObjectType) X(HYPRE_IJMatrixSetDiagOffdSizes) \
  X(HYPRE_IJMatrixInitialize) X(HYPRE_IJMatrixSetValues) X(HYPRE_IJMatrixAssemble)         \
  X(HYPRE_IJMatrixGetObject) X(HYPRE_IJMatrixDestroy)                                      \
  X(HYPRE_IJVectorCreate) X(HYPRE_IJVectorSetObjectType) X(HYPRE_IJVectorInitialize)       \
  X(HYPRE_IJVectorSetValues) X(HYPRE_IJVectorGetValues) X(HYPRE_IJVectorAssemble)          \
  X(HYPRE_IJVectorGetObject) X(HYPRE_IJVectorDestroy)                                      \
  X(HYPRE_BoomerAMGCreate) X(HYPRE_BoomerAMGDestroy) X(HYPRE_BoomerAMGSetPrintLevel)       \
  X(HYPRE_BoomerAMGSetMaxIter) X(HYPRE_BoomerAMGSetTol) X(HYPRE_BoomerAMGSetNumFunctions)  \
  X(HYPRE_BoomerAMGSetAggNumLevels) X(HYPRE_BoomerAMGSetAggInterpType)                     \
  X(HYPRE_BoomerAMGSetup) X(HYPRE_BoomerAMGSolve)                                          \
  X(HYPRE_ParCSRPCGCreate) X(HYPRE_ParCSRPCGDestroy) X(HYPRE_ParCSRPCGSetup)               \
  X(HYPRE_ParCSRPCGSolve) X(HYPRE_PCGSetTol) X(HYPRE_PCGSetAbsoluteTol)                    \
  X(HYPRE_PCGSetMaxIter) X(HYPRE_PCGSetTwoNorm) X(HYPRE_PCGSetRecomputeResidual)           \
  X(HYPRE_PCGSetPrintLevel) X(HYPRE_PCGSetPrecond) X(HYPRE_PCGGetNumIterations)            \
  X(HYPRE_PCGGetConverged) X(HYPRE_PCGGetFinalRelativeResidualNorm)                        \
  X(MPI_Initialized) X(MPI_Init) X(MPI_Finalized) X(MPI_Finalize)

/// How each failure to load begins; said once on standard error.
constexpr const char* kAmgUnavailable = "algebraic multigrid (solver=\"amg\") is not available";

/// Hypre's file: the build's (Debian's soname, FOSSSim/CMakeLists.txt), or the environment's
/// FOSSSIM_HYPRE_LIBRARY (another hypre, or a missing one to test the fallback). kGlobal:
/// OpenMPI opens its components (mca_*.so) with dlopen, and they take libmpi's and
/// libopen-pal's symbols from the global scope. The library stays open until exit (OpenMPI
/// cannot be started again once finalised).
SharedLibrary open_hypre() {
  const char* chosen = std::getenv("FOSSSIM_HYPRE_LIBRARY");
  return SharedLibrary::open({chosen && *chosen ? chosen : FOSSSIM_HYPRE_LIBRARY}, kAmgUnavailable,
                             "libhypre-2.26.0", SharedLibrary::Scope::kGlobal);
}

// The functions are found on the library's handle, which searches it and its dependencies
// (libmpi) only. That matters: MUMPS's sequential MPI stubs, which the program links, define
// MPI_Init and MPI_Finalize too, and a global lookup would find them first. (Hypre itself binds
// MPI_Comm_rank and MPI_Wtime, which the stubs also define, to the stubs, global scope first: in
// one process they answer as OpenMPI would, rank 0 and the wall clock.)
struct HypreApi {
  SharedLibrary library = open_hypre();
  FOSSSIM_HYPRE_FUNCTIONS(FOSSSIM_LIBRARY_FUNCTION)
  /// MPI_COMM_SELF: in OpenMPI the address of a library object (ompi_mpi_comm_self), resolved
  /// like the functions; in other MPIs a constant.
#ifdef OPEN_MPI
  MPI_Comm comm_self = library.symbol<MPI_Comm>("ompi_mpi_comm_self");
#else
  MPI_Comm comm_self = MPI_COMM_SELF;
#endif
};

const HypreApi* hypre_api();

/// Starts MPI for hypre, which Debian builds with it, and finalises both at exit. A single
/// process needs no launcher: OpenMPI's "singleton" start, kept from spawning its runtime daemon
/// (half the start-up time) unless the environment says otherwise.
void start_mpi(const HypreApi& api) {
  int initialized = 0;
  api.MPI_Initialized(&initialized);
  if (!initialized) {
    setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
    const bool started = api.MPI_Init(nullptr, nullptr) == MPI_SUCCESS;
    if (started) api.MPI_Initialized(&initialized);
    if (!initialized) {
      throw Error(ErrorKind::kUnavailable,
                  std::string(kAmgUnavailable) +
                      (started ? ": MPI did not start (OpenMPI)" : ": MPI_Init failed (OpenMPI)"));
    }
  }
  api.HYPRE_Init();
  std::atexit([] {
    const HypreApi& loaded = *hypre_api();
    int finalized = 0;
    loaded.MPI_Finalized(&finalized);
    if (!finalized) {
      loaded.HYPRE_Finalize();
      loaded.MPI_Finalize();
    }
  });
}

/// The loaded table, or nullptr when hypre cannot be loaded (said once on stderr).
const HypreApi* hypre_api() {
  static const HypreApi* const api = []() -> const HypreApi* {
    try {
      static const HypreApi loaded;
      start_mpi(loaded);
      return &loaded;
    } catch (const Error& error) {
      std::fprintf(stderr, "FOSSSim: %s. The sparse direct solvers answer instead.\n",
                   error.what());
      return nullptr;
    }
  }();
  return api;
}

/// The preconditioner's setup inside PCG: none, the hierarchy is built by AmgSolver::setup.
HYPRE_Int no_setup(HYPRE_Solver, HYPRE_Matrix, HYPRE_Vector, HYPRE_Vector) { return 0; }

}  // namespace

struct AmgSolver::Hypre {
  explicit Hypre(const HypreApi& loaded) : api(&loaded) {}

  const HypreApi* api;
  int n = 0;
  HYPRE_IJMatrix matrix = nullptr;  // the hierarchy's
  HYPRE_ParCSRMatrix parcsr = nullptr;
  HYPRE_IJMatrix system = nullptr;  // CG's, when another than the hierarchy's
  HYPRE_ParCSRMatrix system_parcsr = nullptr;
  HYPRE_IJVector rhs = nullptr, solution = nullptr;
  HYPRE_ParVector par_rhs = nullptr, par_solution = nullptr;
  HYPRE_Solver amg = nullptr;
  std::vector<HYPRE_BigInt> indices;  // 0 … n−1
  std::vector<double> zeros;
  bool ready = false;

  ~Hypre() { release(); }

  void release() {
    if (amg) api->HYPRE_BoomerAMGDestroy(amg);
    if (matrix) api->HYPRE_IJMatrixDestroy(matrix);
    drop_system();
    if (rhs) api->HYPRE_IJVectorDestroy(rhs);
    if (solution) api->HYPRE_IJVectorDestroy(solution);
    amg = nullptr;
    matrix = nullptr;
    rhs = solution = nullptr;
    parcsr = nullptr;
    par_rhs = par_solution = nullptr;
    ready = false;
  }

  void drop_system() {
    if (system) api->HYPRE_IJMatrixDestroy(system);
    system = nullptr;
    system_parcsr = nullptr;
  }

  /// A's rows as a hypre matrix; false when hypre refuses them. Hypre takes rows: A's
  /// compressed rows (a row-major copy; A's columns are its rows only when A is symmetric).
  bool make_matrix(const SparseMatrix& A, HYPRE_IJMatrix* ij, HYPRE_ParCSRMatrix* par) const {
    const Eigen::SparseMatrix<double, Eigen::RowMajor, int> rows = A;
    std::vector<HYPRE_Int> sizes(n), offd(n, 0);
    for (int r = 0; r < n; ++r) sizes[r] = rows.outerIndexPtr()[r + 1] - rows.outerIndexPtr()[r];
    api->HYPRE_IJMatrixCreate(api->comm_self, 0, n - 1, 0, n - 1, ij);
    api->HYPRE_IJMatrixSetObjectType(*ij, HYPRE_PARCSR);
    api->HYPRE_IJMatrixSetDiagOffdSizes(*ij, sizes.data(), offd.data());
    api->HYPRE_IJMatrixInitialize(*ij);
    api->HYPRE_IJMatrixSetValues(*ij, n, sizes.data(), indices.data(), rows.innerIndexPtr(),
                            rows.valuePtr());
    if (api->HYPRE_IJMatrixAssemble(*ij) != 0) {
      api->HYPRE_ClearAllErrors();
      return false;
    }
    api->HYPRE_IJMatrixGetObject(*ij, reinterpret_cast<void**>(par));
    return true;
  }

  void make_vectors() {
    for (HYPRE_IJVector* v : {&rhs, &solution}) {
      api->HYPRE_IJVectorCreate(api->comm_self, 0, n - 1, v);
      api->HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
      api->HYPRE_IJVectorInitialize(*v);
      api->HYPRE_IJVectorSetValues(*v, n, indices.data(), zeros.data());
      api->HYPRE_IJVectorAssemble(*v);
    }
    api->HYPRE_IJVectorGetObject(rhs, reinterpret_cast<void**>(&par_rhs));
    api->HYPRE_IJVectorGetObject(solution, reinterpret_cast<void**>(&par_solution));
  }

  void set(HYPRE_IJVector v, const double* values) const {
    api->HYPRE_IJVectorSetValues(v, n, indices.data(), values);
  }
  void get(HYPRE_IJVector v, double* values) const {
    api->HYPRE_IJVectorGetValues(v, n, indices.data(), values);
  }
};

bool amg_built_in() { return true; }

bool amg_available() { return hypre_api() != nullptr; }

AmgSolver::AmgSolver() = default;
AmgSolver::~AmgSolver() = default;

bool AmgSolver::ready() const { return hypre_ && hypre_->ready; }

bool AmgSolver::setup(const SparseMatrix& A, int components) {
  if (A.rows() != A.cols() || A.rows() == 0) return false;
  if (!hypre_) {
    const HypreApi* api = hypre_api();
    if (!api) return false;
    hypre_ = std::make_unique<Hypre>(*api);
  }
  Hypre& h = *hypre_;
  const int n = static_cast<int>(A.rows());
  if (h.n != n) {
    h.release();
    h.n = n;
    h.indices.resize(n);
    std::iota(h.indices.begin(), h.indices.end(), 0);
    h.zeros.assign(n, 0.0);
    h.make_vectors();
  } else {
    if (h.amg) h.api->HYPRE_BoomerAMGDestroy(h.amg);
    if (h.matrix) h.api->HYPRE_IJMatrixDestroy(h.matrix);
    h.drop_system();
    h.amg = nullptr;
    h.matrix = nullptr;
  }
  h.ready = false;
  if (!h.make_matrix(A, &h.matrix, &h.parcsr)) return false;

  h.api->HYPRE_BoomerAMGCreate(&h.amg);
  h.api->HYPRE_BoomerAMGSetPrintLevel(h.amg, 0);
  h.api->HYPRE_BoomerAMGSetMaxIter(h.amg, 1);  // one V-cycle per application
  h.api->HYPRE_BoomerAMGSetTol(h.amg, 0.0);
  if (components > 1) h.api->HYPRE_BoomerAMGSetNumFunctions(h.amg, components);
  // Aggressive coarsening on the finest level, interpolated by the matrix-based extended+i
  // formula (hypre's AggInterpType 6). With hypre's defaults (HMIS, extended+i, at most 4
  // weights a row) the 2D step matrices kept half their unknowns on the second level, which
  // held as many entries as the first: operator complexity 2.48 on the 316×316 damped cloth.
  // Coarsening the first level twice over keeps 8% of its unknowns, complexity 1.23: a V-cycle
  // does half the work and the hierarchy costs half as much to build, for 15 iterations a solve
  // instead of 13 (cloth; 23 instead of 17 on the CST sheets). Measured with bench_elastic,
  // docs/solvers.md, "Algebraic multigrid".
  h.api->HYPRE_BoomerAMGSetAggNumLevels(h.amg, 1);
  h.api->HYPRE_BoomerAMGSetAggInterpType(h.amg, 6);
  const HYPRE_Int status = h.api->HYPRE_BoomerAMGSetup(h.amg, h.parcsr, h.par_rhs, h.par_solution);
  if (status != 0) {
    h.api->HYPRE_ClearAllErrors();
    return false;
  }
  h.ready = true;
  return true;
}

bool AmgSolver::set_matrix(const SparseMatrix& A) {
  if (!ready() || A.rows() != hypre_->n || A.cols() != hypre_->n) return false;
  Hypre& h = *hypre_;
  h.drop_system();
  return h.make_matrix(A, &h.system, &h.system_parcsr);
}

void AmgSolver::apply(const double* r, double* z) const {
  Hypre& h = *hypre_;
  h.set(h.rhs, r);
  h.set(h.solution, h.zeros.data());
  h.api->HYPRE_BoomerAMGSolve(h.amg, h.parcsr, h.par_rhs, h.par_solution);
  h.api->HYPRE_ClearAllErrors();  // "did not converge" in one cycle is the rule here, not an error
  h.get(h.solution, z);
}

KrylovResult AmgSolver::conjugate_gradients(const Vector& b, Vector& x, double relative_tolerance,
                                            int max_iterations) const {
  Hypre& h = *hypre_;
  KrylovResult result;
  h.set(h.rhs, b.data());
  h.set(h.solution, x.data());
  HYPRE_Solver pcg = nullptr;
  h.api->HYPRE_ParCSRPCGCreate(h.api->comm_self, &pcg);
  h.api->HYPRE_PCGSetTol(pcg, relative_tolerance);
  h.api->HYPRE_PCGSetAbsoluteTol(pcg, 0.0);
  h.api->HYPRE_PCGSetMaxIter(pcg, max_iterations);
  h.api->HYPRE_PCGSetTwoNorm(pcg, 1);
  h.api->HYPRE_PCGSetRecomputeResidual(pcg, 1);
  h.api->HYPRE_PCGSetPrintLevel(pcg, 0);
  h.api->HYPRE_PCGSetPrecond(
      pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(h.api->HYPRE_BoomerAMGSolve),
                      reinterpret_cast<HYPRE_PtrToSolverFcn>(no_setup), h.amg);
  HYPRE_ParCSRMatrix system = h.system_parcsr ? h.system_parcsr : h.parcsr;
  h.api->HYPRE_ParCSRPCGSetup(pcg, system, h.par_rhs, h.par_solution);
  h.api->HYPRE_ParCSRPCGSolve(pcg, system, h.par_rhs, h.par_solution);
  HYPRE_Int iterations = 0, converged = 0;
  double relative = 0.0;
  h.api->HYPRE_PCGGetNumIterations(pcg, &iterations);
  h.api->HYPRE_PCGGetConverged(pcg, &converged);
  h.api->HYPRE_PCGGetFinalRelativeResidualNorm(pcg, &relative);
  h.api->HYPRE_ParCSRPCGDestroy(pcg);
  h.api->HYPRE_ClearAllErrors();
  h.get(h.solution, x.data());
  result.iterations = iterations;
  result.converged = converged != 0;
  result.residual = relative * b.norm();
  return result;
}

}  // namespace fosssim

#else  // built without hypre

namespace fosssim {

struct AmgSolver::Hypre {};

bool amg_built_in() { return false; }
bool amg_available() { return false; }
AmgSolver::AmgSolver() = default;
AmgSolver::~AmgSolver() = default;
bool AmgSolver::setup(const SparseMatrix&, int) { return false; }
bool AmgSolver::ready() const { return false; }
bool AmgSolver::set_matrix(const SparseMatrix&) { return false; }
void AmgSolver::apply(const double*, double*) const {}
KrylovResult AmgSolver::conjugate_gradients(const Vector&, Vector&, double, int) const {
  return {};
}

}  // namespace fosssim

#endif
