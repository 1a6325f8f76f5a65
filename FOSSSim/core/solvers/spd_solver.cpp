#include "core/solvers/spd_solver.h"

namespace fosssim {

bool SpdSolver::factor(const SparseMatrix& A, Method method) {
  method_ = method;
  size_ = static_cast<int>(A.rows());
  if (method == Method::kDense) {
    dense_.compute(Eigen::MatrixXd(A));
    return dense_.info() == Eigen::Success;
  }
  sparse_.emplace(CholeskyOptions{});
  sparse_->analyze(A);
  pattern_nonzeros_ = A.nonZeros();
  return sparse_->factorize(A);
}

bool SpdSolver::refactor(const SparseMatrix& A) {
  if (method_ == Method::kDense || !sparse_ || A.rows() != size_ ||
      A.nonZeros() != pattern_nonzeros_) {
    return factor(A, method_);
  }
  return sparse_->factorize(A);
}

long SpdSolver::factor_nonzeros() const {
  if (method_ == Method::kDense) return static_cast<long>(size_) * (size_ + 1) / 2;
  return static_cast<long>(sparse_->factor_nonzeros());
}

template <int C>
void SpdSolver::solve_in_place(Points<C>& X) const {
  if (method_ == Method::kDense) {
    dense_.solveInPlace(X);
    return;
  }
  columns_ = X;  // column-major copy
  sparse_->solve(columns_.data(), columns_.data(), C);
  X = columns_;
}

template void SpdSolver::solve_in_place<2>(Points<2>&) const;
template void SpdSolver::solve_in_place<3>(Points<3>&) const;

}  // namespace fosssim
