#include "core/solvers/amg_solver.h"

#if FOSSSIM_HAVE_HYPRE

// OpenMPI's C++ bindings are not used.
#define OMPI_SKIP_MPICXX 1
#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <cstdlib>
#include <numeric>
#include <vector>

namespace fosssim {

namespace {

/// Initialises MPI once for hypre (Debian's hypre is built with OpenMPI), unless the program
/// did; false when that fails. A single process needs no launcher: OpenMPI's "singleton" start,
/// kept from spawning its runtime daemon (half the start-up time) unless the environment says
/// otherwise. MUMPS's sequential MPI stubs define MPI_Init too: the build links OpenMPI first
/// (cmake/FOSSSimDependencies.cmake), and MPI_Initialized, which the stubs lack, checks it.
bool mpi_ready() {
  static const bool ready = [] {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (initialized) return true;
    setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
    if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) return false;
    MPI_Initialized(&initialized);
    if (!initialized) return false;
    HYPRE_Init();
    std::atexit([] {
      int finalized = 0;
      MPI_Finalized(&finalized);
      if (!finalized) {
        HYPRE_Finalize();
        MPI_Finalize();
      }
    });
    return true;
  }();
  return ready;
}

/// The preconditioner's setup inside PCG: none, the hierarchy is built by AmgSolver::setup.
HYPRE_Int no_setup(HYPRE_Solver, HYPRE_Matrix, HYPRE_Vector, HYPRE_Vector) { return 0; }

}  // namespace

struct AmgSolver::Hypre {
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
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (matrix) HYPRE_IJMatrixDestroy(matrix);
    drop_system();
    if (rhs) HYPRE_IJVectorDestroy(rhs);
    if (solution) HYPRE_IJVectorDestroy(solution);
    amg = nullptr;
    matrix = nullptr;
    rhs = solution = nullptr;
    parcsr = nullptr;
    par_rhs = par_solution = nullptr;
    ready = false;
  }

  void drop_system() {
    if (system) HYPRE_IJMatrixDestroy(system);
    system = nullptr;
    system_parcsr = nullptr;
  }

  /// A's rows as a hypre matrix; false when hypre refuses them. Hypre takes rows: A's
  /// compressed rows (a row-major copy; A's columns are its rows only when A is symmetric).
  bool make_matrix(const SparseMatrix& A, HYPRE_IJMatrix* ij, HYPRE_ParCSRMatrix* par) const {
    const Eigen::SparseMatrix<double, Eigen::RowMajor, int> rows = A;
    std::vector<HYPRE_Int> sizes(n), offd(n, 0);
    for (int r = 0; r < n; ++r) sizes[r] = rows.outerIndexPtr()[r + 1] - rows.outerIndexPtr()[r];
    HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, n - 1, 0, n - 1, ij);
    HYPRE_IJMatrixSetObjectType(*ij, HYPRE_PARCSR);
    HYPRE_IJMatrixSetDiagOffdSizes(*ij, sizes.data(), offd.data());
    HYPRE_IJMatrixInitialize(*ij);
    HYPRE_IJMatrixSetValues(*ij, n, sizes.data(), indices.data(), rows.innerIndexPtr(),
                            rows.valuePtr());
    if (HYPRE_IJMatrixAssemble(*ij) != 0) {
      HYPRE_ClearAllErrors();
      return false;
    }
    HYPRE_IJMatrixGetObject(*ij, reinterpret_cast<void**>(par));
    return true;
  }

  void make_vectors() {
    for (HYPRE_IJVector* v : {&rhs, &solution}) {
      HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, v);
      HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
      HYPRE_IJVectorInitialize(*v);
      HYPRE_IJVectorSetValues(*v, n, indices.data(), zeros.data());
      HYPRE_IJVectorAssemble(*v);
    }
    HYPRE_IJVectorGetObject(rhs, reinterpret_cast<void**>(&par_rhs));
    HYPRE_IJVectorGetObject(solution, reinterpret_cast<void**>(&par_solution));
  }

  void set(HYPRE_IJVector v, const double* values) const {
    HYPRE_IJVectorSetValues(v, n, indices.data(), values);
  }
  void get(HYPRE_IJVector v, double* values) const {
    HYPRE_IJVectorGetValues(v, n, indices.data(), values);
  }
};

bool amg_available() { return true; }

AmgSolver::AmgSolver() = default;
AmgSolver::~AmgSolver() = default;

bool AmgSolver::ready() const { return hypre_ && hypre_->ready; }

bool AmgSolver::setup(const SparseMatrix& A, int components) {
  if (!mpi_ready() || A.rows() != A.cols() || A.rows() == 0) return false;
  if (!hypre_) hypre_ = std::make_unique<Hypre>();
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
    if (h.amg) HYPRE_BoomerAMGDestroy(h.amg);
    if (h.matrix) HYPRE_IJMatrixDestroy(h.matrix);
    h.drop_system();
    h.amg = nullptr;
    h.matrix = nullptr;
  }
  h.ready = false;
  if (!h.make_matrix(A, &h.matrix, &h.parcsr)) return false;

  HYPRE_BoomerAMGCreate(&h.amg);
  HYPRE_BoomerAMGSetPrintLevel(h.amg, 0);
  HYPRE_BoomerAMGSetMaxIter(h.amg, 1);  // one V-cycle per application
  HYPRE_BoomerAMGSetTol(h.amg, 0.0);
  if (components > 1) HYPRE_BoomerAMGSetNumFunctions(h.amg, components);
  const HYPRE_Int status = HYPRE_BoomerAMGSetup(h.amg, h.parcsr, h.par_rhs, h.par_solution);
  if (status != 0) {
    HYPRE_ClearAllErrors();
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
  HYPRE_BoomerAMGSolve(h.amg, h.parcsr, h.par_rhs, h.par_solution);
  HYPRE_ClearAllErrors();  // "did not converge" in one cycle is the rule here, not an error
  h.get(h.solution, z);
}

KrylovResult AmgSolver::conjugate_gradients(const Vector& b, Vector& x, double relative_tolerance,
                                            int max_iterations) const {
  Hypre& h = *hypre_;
  KrylovResult result;
  h.set(h.rhs, b.data());
  h.set(h.solution, x.data());
  HYPRE_Solver pcg = nullptr;
  HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &pcg);
  HYPRE_PCGSetTol(pcg, relative_tolerance);
  HYPRE_PCGSetAbsoluteTol(pcg, 0.0);
  HYPRE_PCGSetMaxIter(pcg, max_iterations);
  HYPRE_PCGSetTwoNorm(pcg, 1);
  HYPRE_PCGSetRecomputeResidual(pcg, 1);
  HYPRE_PCGSetPrintLevel(pcg, 0);
  HYPRE_PCGSetPrecond(pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                      reinterpret_cast<HYPRE_PtrToSolverFcn>(no_setup), h.amg);
  HYPRE_ParCSRMatrix system = h.system_parcsr ? h.system_parcsr : h.parcsr;
  HYPRE_ParCSRPCGSetup(pcg, system, h.par_rhs, h.par_solution);
  HYPRE_ParCSRPCGSolve(pcg, system, h.par_rhs, h.par_solution);
  HYPRE_Int iterations = 0, converged = 0;
  double relative = 0.0;
  HYPRE_PCGGetNumIterations(pcg, &iterations);
  HYPRE_PCGGetConverged(pcg, &converged);
  HYPRE_PCGGetFinalRelativeResidualNorm(pcg, &relative);
  HYPRE_ParCSRPCGDestroy(pcg);
  HYPRE_ClearAllErrors();
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
