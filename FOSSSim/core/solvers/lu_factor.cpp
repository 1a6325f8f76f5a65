#include "core/solvers/lu_factor.h"

#include <umfpack.h>

#include <stdexcept>

#include "core/solvers/solver_failure.h"
#include "core/solvers/solver_libraries.h"

namespace fosssim {

LuFactor::LuFactor() : control_(UMFPACK_CONTROL), info_(UMFPACK_INFO) {
  umfpack_library().umfpack_di_defaults(control_.data());
  control_[UMFPACK_PRL] = 0;     // never print
  control_[UMFPACK_IRSTEP] = 0;  // no iterative refinement: GMRES refines
}

LuFactor::~LuFactor() {
  free_numeric();
  if (symbolic_ != nullptr) umfpack_library().umfpack_di_free_symbolic(&symbolic_);
}

void LuFactor::free_numeric() {
  if (numeric_ != nullptr) umfpack_library().umfpack_di_free_numeric(&numeric_);
  factored_ = false;
}

void LuFactor::analyze(const SparseMatrix& A) {
  if (A.rows() != A.cols()) throw std::logic_error("LuFactor: the matrix is not square");
  free_numeric();
  if (symbolic_ != nullptr) umfpack_library().umfpack_di_free_symbolic(&symbolic_);
  size_ = static_cast<int>(A.rows());
  const int status = umfpack_library().umfpack_di_symbolic(
      size_, size_, A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(), &symbolic_, control_.data(),
      info_.data());
  if (status != UMFPACK_OK) throw SolverFailure("UMFPACK: the analysis failed");
  integer_work_.resize(static_cast<std::size_t>(size_));
  work_.resize(static_cast<std::size_t>(size_));
}

bool LuFactor::factorize(const SparseMatrix& A) {
  if (symbolic_ == nullptr || A.rows() != size_) {
    throw std::logic_error("LuFactor::factorize: the pattern was not analysed");
  }
  free_numeric();
  const int status =
      umfpack_library().umfpack_di_numeric(A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(),
                                           symbolic_, &numeric_, control_.data(), info_.data());
  factor_nonzeros_ = info_[UMFPACK_LNZ] + info_[UMFPACK_UNZ];
  factor_flops_ = info_[UMFPACK_FLOPS];
  factored_ = status == UMFPACK_OK;
  if (!factored_) free_numeric();
  return factored_;
}

void LuFactor::solve(const double* b, double* x) const {
  if (!factored_) throw std::logic_error("LuFactor::solve without a factor");
  const int status = umfpack_library().umfpack_di_wsolve(UMFPACK_A, nullptr, nullptr, nullptr, x, b,
                                                         numeric_, control_.data(), info_.data(),
                                                         integer_work_.data(), work_.data());
  if (status != UMFPACK_OK) throw SolverFailure("UMFPACK: the solve failed");
}

}  // namespace fosssim
