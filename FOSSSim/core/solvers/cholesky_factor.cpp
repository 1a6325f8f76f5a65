#include "core/solvers/cholesky_factor.h"

#include <cholmod.h>

#include <cstring>
#include <stdexcept>

#include "core/solvers/solver_failure.h"
#include "core/solvers/solver_libraries.h"

namespace fosssim {

/// CHOLMOD's state: its workspace (cholmod_common), the factor, and the dense buffers that
/// cholmod_solve2 keeps between solves.
struct CholeskyFactor::Cholmod {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  cholmod_dense* x = nullptr;  // solution, reused while the number of columns is the same
  cholmod_dense* y = nullptr;  // workspace of cholmod_solve2
  cholmod_dense* e = nullptr;  // workspace of cholmod_solve2

  Cholmod() { cholmod_library().cholmod_start(&common); }
  ~Cholmod() {
    free_factor();
    cholmod_library().cholmod_free_dense(&x, &common);
    cholmod_library().cholmod_free_dense(&y, &common);
    cholmod_library().cholmod_free_dense(&e, &common);
    cholmod_library().cholmod_finish(&common);
  }
  void free_factor() {
    if (factor != nullptr) cholmod_library().cholmod_free_factor(&factor, &common);
  }
};

namespace {

/// A's storage as CHOLMOD's matrix, without copying, of which CHOLMOD reads one triangle.
cholmod_sparse view_triangle(const SparseMatrix& A, CholeskyOptions::Triangle triangle) {
  cholmod_sparse view{};
  view.nrow = static_cast<std::size_t>(A.rows());
  view.ncol = static_cast<std::size_t>(A.cols());
  view.nzmax = static_cast<std::size_t>(A.nonZeros());
  view.p = const_cast<SparseMatrix::StorageIndex*>(A.outerIndexPtr());
  view.i = const_cast<SparseMatrix::StorageIndex*>(A.innerIndexPtr());
  view.x = const_cast<double*>(A.valuePtr());
  view.stype = triangle == CholeskyOptions::Triangle::kUpper ? 1 : -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

/// An n×columns column-major array as CHOLMOD's dense matrix, without copying.
cholmod_dense view_dense(const double* data, int n, int columns) {
  cholmod_dense view{};
  view.nrow = static_cast<std::size_t>(n);
  view.ncol = static_cast<std::size_t>(columns);
  view.nzmax = view.nrow * view.ncol;
  view.d = view.nrow;
  view.x = const_cast<double*>(data);
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  return view;
}

}  // namespace

CholeskyFactor::CholeskyFactor(CholeskyOptions options)
    : options_(options), cholmod_(std::make_unique<Cholmod>()) {
  cholmod_common& c = cholmod_->common;
  c.print = 0;  // failures are reported through return values, never printed
  c.nmethods = 1;
  c.method[0].ordering =
      options.ordering == CholeskyOptions::Ordering::kMetis ? CHOLMOD_METIS : CHOLMOD_AMD;
  c.postorder = 1;
  c.supernodal = options.layout == CholeskyOptions::Layout::kSimplicial   ? CHOLMOD_SIMPLICIAL
                 : options.layout == CholeskyOptions::Layout::kSupernodal ? CHOLMOD_SUPERNODAL
                                                                          : CHOLMOD_AUTO;
  // A simplicial factor is computed as L Lᵀ (not L D Lᵀ), which stops at the first pivot that
  // is not positive: positive definiteness is checked alike in both layouts.
  c.final_asis = 0;
  c.final_ll = 1;
  c.final_super = 1;
  c.final_pack = 1;
  c.final_monotonic = 1;
  c.quick_return_if_not_posdef = 1;
}

CholeskyFactor::~CholeskyFactor() = default;

void CholeskyFactor::analyze(const SparseMatrix& A) {
  if (A.rows() != A.cols()) throw std::logic_error("CholeskyFactor: the matrix is not square");
  cholmod_->free_factor();
  factored_ = false;
  size_ = static_cast<int>(A.rows());
  cholmod_sparse view = view_triangle(A, options_.triangle);
  cholmod_->factor = cholmod_library().cholmod_analyze(&view, &cholmod_->common);
  if (cholmod_->factor == nullptr) throw SolverFailure("CHOLMOD: the analysis failed");
}

bool CholeskyFactor::is_analyzed() const { return cholmod_->factor != nullptr; }

bool CholeskyFactor::factorize(const SparseMatrix& A) {
  if (!is_analyzed() || A.rows() != size_) {
    throw std::logic_error("CholeskyFactor::factorize: the pattern was not analysed");
  }
  cholmod_sparse view = view_triangle(A, options_.triangle);
  const int ok = cholmod_library().cholmod_factorize(&view, cholmod_->factor, &cholmod_->common);
  factored_ = ok != 0 && cholmod_->common.status == CHOLMOD_OK;
  return factored_;
}

void CholeskyFactor::solve(const double* B, double* X, int columns) const {
  if (!factored_) throw std::logic_error("CholeskyFactor::solve without a factor");
  cholmod_dense b = view_dense(B, size_, columns);
  Cholmod& c = *cholmod_;
  if (cholmod_library().cholmod_solve2(CHOLMOD_A, c.factor, &b, nullptr, &c.x, nullptr, &c.y, &c.e,
                                       &c.common) == 0) {
    throw SolverFailure("CHOLMOD: the solve failed");
  }
  std::memcpy(X, c.x->x, sizeof(double) * static_cast<std::size_t>(size_) * columns);
}

Vector CholeskyFactor::solve(const Vector& b) const {
  Vector x(b.size());
  solve(b.data(), x.data(), 1);
  return x;
}

double CholeskyFactor::factor_nonzeros() const { return cholmod_->common.lnz; }

double CholeskyFactor::factor_flops() const { return cholmod_->common.fl; }

bool CholeskyFactor::is_supernodal() const {
  return cholmod_->factor != nullptr && cholmod_->factor->is_super != 0;
}

}  // namespace fosssim
