// The sparse direct factors of a build without SuiteSparse and MUMPS (the WebAssembly build,
// FOSSSIM_WEB): CholeskyFactor on Eigen's simplicial LLᵀ with its AMD ordering, so that the
// integrators that factor a constant SPD matrix (fast mass-springs, quasi-Newton) still run on
// large 3D meshes (their results then differ from the native CHOLMOD's in the last bits);
// LdltFactor and LuFactor refuse to run. StepSolver sends no system to them unless the scene
// asks for the sparse direct solvers by name (core/solvers/step_solver.cpp).

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <cstring>
#include <stdexcept>

#include "core/error.h"
#include "core/solvers/cholesky_factor.h"
#include "core/solvers/ldlt_factor.h"
#include "core/solvers/lu_factor.h"

namespace fosssim {

namespace {
[[noreturn]] void unavailable(const char* what) {
  throw Error(ErrorKind::kUnavailable,
              std::string(what) +
                  " is not in this build (the WebAssembly build has no SuiteSparse or MUMPS): "
                  "choose the Eigen solvers (solver=\"eigen\")");
}
}  // namespace

struct CholeskyFactor::Cholmod {  // the name of the native build's workspace; Eigen's here
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> lower;
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Upper, Eigen::AMDOrdering<int>> upper;
  bool analysed = false;
};

CholeskyFactor::CholeskyFactor(CholeskyOptions options)
    : options_(options), cholmod_(std::make_unique<Cholmod>()) {}

CholeskyFactor::~CholeskyFactor() = default;

void CholeskyFactor::analyze(const SparseMatrix& A) {
  if (A.rows() != A.cols()) throw std::logic_error("CholeskyFactor: the matrix is not square");
  factored_ = false;
  size_ = static_cast<int>(A.rows());
  if (options_.triangle == CholeskyOptions::Triangle::kLower) {
    cholmod_->lower.analyzePattern(A);
  } else {
    cholmod_->upper.analyzePattern(A);
  }
  cholmod_->analysed = true;
}

bool CholeskyFactor::is_analyzed() const { return cholmod_->analysed; }

bool CholeskyFactor::factorize(const SparseMatrix& A) {
  if (!is_analyzed() || A.rows() != size_) {
    throw std::logic_error("CholeskyFactor::factorize: the pattern was not analysed");
  }
  if (options_.triangle == CholeskyOptions::Triangle::kLower) {
    cholmod_->lower.factorize(A);
    factored_ = cholmod_->lower.info() == Eigen::Success;
  } else {
    cholmod_->upper.factorize(A);
    factored_ = cholmod_->upper.info() == Eigen::Success;
  }
  return factored_;
}

void CholeskyFactor::solve(const double* B, double* X, int columns) const {
  if (!factored_) throw std::logic_error("CholeskyFactor::solve without a factor");
  const Eigen::Map<const Eigen::MatrixXd> b(B, size_, columns);
  const Eigen::MatrixXd x = options_.triangle == CholeskyOptions::Triangle::kLower
                                ? Eigen::MatrixXd(cholmod_->lower.solve(b))
                                : Eigen::MatrixXd(cholmod_->upper.solve(b));
  std::memcpy(X, x.data(), sizeof(double) * static_cast<std::size_t>(size_) * columns);
}

Vector CholeskyFactor::solve(const Vector& b) const {
  Vector x(b.size());
  solve(b.data(), x.data(), 1);
  return x;
}

double CholeskyFactor::factor_nonzeros() const {
  if (!factored_) return 0.0;
  return options_.triangle == CholeskyOptions::Triangle::kLower
             ? static_cast<double>(cholmod_->lower.matrixL().nestedExpression().nonZeros())
             : static_cast<double>(cholmod_->upper.matrixU().nestedExpression().nonZeros());
}

double CholeskyFactor::factor_flops() const { return 0.0; }  // not counted by Eigen

bool CholeskyFactor::is_supernodal() const { return false; }

struct LdltFactor::Mumps {};

LdltFactor::LdltFactor(FactorPrecision precision) : precision_(precision) {}
LdltFactor::~LdltFactor() = default;
void LdltFactor::analyze(const SparseMatrix&) { unavailable("MUMPS (sparse LDLT)"); }
bool LdltFactor::factorize(const SparseMatrix&) { unavailable("MUMPS (sparse LDLT)"); }
void LdltFactor::solve(const double*, double*) const { unavailable("MUMPS (sparse LDLT)"); }

LuFactor::LuFactor() = default;
LuFactor::~LuFactor() = default;
void LuFactor::free_numeric() { numeric_ = nullptr; }  // there is never one to free
void LuFactor::analyze(const SparseMatrix&) { unavailable("UMFPACK (sparse LU)"); }
bool LuFactor::factorize(const SparseMatrix&) { unavailable("UMFPACK (sparse LU)"); }
void LuFactor::solve(const double*, double*) const { unavailable("UMFPACK (sparse LU)"); }

}  // namespace fosssim
