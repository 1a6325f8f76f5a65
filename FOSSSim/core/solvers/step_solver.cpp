#include "core/solvers/step_solver.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

namespace {
/// Accept an LDLᵀ solution when its residual is this small relative to the system's scale.
constexpr double kResidualTolerance = 1e-12;

bool is_accurate(const SparseMatrix& A, const Vector& x, const Vector& b) {
  if (!x.allFinite()) return false;
  const double residual = (A * x - b).norm();
  const double scale = b.norm() + A.norm() * x.norm();
  return residual <= kResidualTolerance * scale;
}
}  // namespace

bool StepSolver::same_pattern(const SparseMatrix& A) const {
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  return static_cast<Eigen::Index>(outer_.size()) == A.outerSize() + 1 &&
         static_cast<Eigen::Index>(inner_.size()) == A.nonZeros() &&
         std::equal(outer_.begin(), outer_.end(), outer) &&
         std::equal(inner_.begin(), inner_.end(), inner);
}

std::optional<Vector> StepSolver::solve(const SparseMatrix& A, const Vector& b) {
  // A scene with no free degree of freedom (no particles, or only fixed ones) has nothing to
  // solve; Eigen's factorizations and norms assert on 0×0 matrices in Debug builds.
  if (A.rows() == 0) return Vector(0);
  if (!same_pattern(A)) {
    outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
    inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
    ldlt_analysed_ = false;
    lu_analysed_ = false;
  }
  if (symmetric_) {
    if (auto x = solve_ldlt(A, b); x && is_accurate(A, *x, b)) {
      last_ = Factorization::kLDLT;
      return x;
    }
  }
  auto x = solve_lu(A, b);
  if (x) last_ = Factorization::kLU;
  return x;
}

std::optional<Vector> StepSolver::solve_ldlt(const SparseMatrix& A, const Vector& b) {
  if (!ldlt_analysed_) {
    ldlt_.analyzePattern(A);
    ldlt_analysed_ = true;
  }
  ldlt_.factorize(A);
  if (ldlt_.info() != Eigen::Success) return std::nullopt;
  Vector x = ldlt_.solve(b);
  return x;
}

std::optional<Vector> StepSolver::solve_lu(const SparseMatrix& A, const Vector& b) {
  if (!lu_analysed_) {
    lu_.analyzePattern(A);
    lu_analysed_ = true;
  }
  lu_.factorize(A);
  if (lu_.info() != Eigen::Success) return std::nullopt;
  Vector x = lu_.solve(b);
  if (!x.allFinite()) return std::nullopt;
  return x;
}

}  // namespace fosssim
