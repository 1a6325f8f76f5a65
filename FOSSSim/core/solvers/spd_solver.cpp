#include "core/solvers/spd_solver.h"

namespace fosssim {

namespace {

/// True when every column of the CSC factor L starts with its diagonal entry, the layout
/// Eigen's up-looking SimplicialLLT produces and our triangular solves rely on.
bool diagonal_comes_first(const SparseMatrix& L) {
  for (Eigen::Index k = 0; k < L.outerSize(); ++k) {
    const auto start = L.outerIndexPtr()[k];
    if (start == L.outerIndexPtr()[k + 1] || L.innerIndexPtr()[start] != k) return false;
  }
  return true;
}

}  // namespace

bool SpdSolver::factor(const SparseMatrix& A, Method method) {
  method_ = method;
  size_ = static_cast<int>(A.rows());
  if (method == Method::kDense) {
    dense_.compute(Eigen::MatrixXd(A));
    return dense_.info() == Eigen::Success;
  }
  sparse_.analyzePattern(A);
  sparse_.factorize(A);
  if (sparse_.info() != Eigen::Success) return false;
  own_sweeps_ = diagonal_comes_first(sparse_.matrixL().nestedExpression());
  return true;
}

bool SpdSolver::refactor(const SparseMatrix& A) {
  if (method_ == Method::kDense || A.rows() != size_) return factor(A, method_);
  sparse_.factorize(A);
  return sparse_.info() == Eigen::Success;
}

long SpdSolver::factor_nonzeros() const {
  if (method_ == Method::kDense) return static_cast<long>(size_) * (size_ + 1) / 2;
  return static_cast<long>(sparse_.matrixL().nestedExpression().nonZeros());
}

template <int C>
void SpdSolver::solve_in_place(Points<C>& X) const {
  if (method_ == Method::kDense) {
    dense_.solveInPlace(X);
  } else if (own_sweeps_) {
    solve_sparse<C>(X);
  } else {
    X = sparse_.solve(X);
  }
}

/// P A Pᵀ = L Lᵀ, so A⁻¹ b = Pᵀ L⁻ᵀ L⁻¹ P b: permute, a forward sweep over L's columns that
/// scatters each solved row into the rows below, a backward sweep that gathers, permute back.
/// Each sweep reads L once and updates all C columns of a row together.
template <int C>
void SpdSolver::solve_sparse(Points<C>& X) const {
  const SparseMatrix& L = sparse_.matrixL().nestedExpression();
  const auto* perm = sparse_.permutationP().indices().data();
  const auto* outer = L.outerIndexPtr();
  const auto* inner = L.innerIndexPtr();
  const double* value = L.valuePtr();
  const int n = size_;
  work_.resize(static_cast<Eigen::Index>(n) * C);
  double* y = work_.data();
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < C; ++c) y[C * perm[i] + c] = X(i, c);
  }
  for (int k = 0; k < n; ++k) {  // L z = y
    double yk[C];
    const double diagonal = value[outer[k]];
    for (int c = 0; c < C; ++c) yk[c] = y[C * k + c] / diagonal;
    for (int c = 0; c < C; ++c) y[C * k + c] = yk[c];
    for (auto p = outer[k] + 1; p < outer[k + 1]; ++p) {
      const double l = value[p];  // loaded once: row may alias value as far as the compiler knows
      double* row = y + C * inner[p];
      for (int c = 0; c < C; ++c) row[c] -= l * yk[c];
    }
  }
  for (int k = n - 1; k >= 0; --k) {  // Lᵀ x = z
    double yk[C];
    for (int c = 0; c < C; ++c) yk[c] = y[C * k + c];
    for (auto p = outer[k] + 1; p < outer[k + 1]; ++p) {
      const double l = value[p];
      const double* row = y + C * inner[p];
      for (int c = 0; c < C; ++c) yk[c] -= l * row[c];
    }
    const double diagonal = value[outer[k]];
    for (int c = 0; c < C; ++c) y[C * k + c] = yk[c] / diagonal;
  }
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < C; ++c) X(i, c) = y[C * perm[i] + c];
  }
}

template void SpdSolver::solve_in_place<2>(Points<2>&) const;
template void SpdSolver::solve_in_place<3>(Points<3>&) const;

}  // namespace fosssim
