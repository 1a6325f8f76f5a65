#include "core/solvers/step_solver.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

namespace {
/// Accept a solution when its residual is this small relative to the system's scale.
constexpr double kResidualTolerance = 1e-12;
/// GMRES never keeps more directions than this; a factor that needs more is replaced.
constexpr int kMaxKrylovIterations = 30;
/// Operations of a numeric factorization are charged at this fraction of those of a solve:
/// dense supernodal blocks run near BLAS-3 speed, triangular sweeps at memory speed
/// (measured on the 81×81 cloth and the tet ball with OpenBLAS, bench_implicit).
constexpr double kSupernodalFlopWeight = 0.2;
constexpr double kSimplicialFlopWeight = 1.0;

double residual_scale(const SparseMatrix& A, const Vector& x, const Vector& b) {
  return b.norm() + A.norm() * x.norm();
}

bool is_accurate(const SparseMatrix& A, const Vector& x, const Vector& b) {
  if (!x.allFinite()) return false;
  return (A * x - b).norm() <= kResidualTolerance * residual_scale(A, x, b);
}

/// The slot of entry (j, i) for every entry (i, j) of A's pattern, or empty when some (j, i)
/// is missing (A is not structurally symmetric).
std::vector<int> transposed_slots(const SparseMatrix& A) {
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  std::vector<int> slots(static_cast<std::size_t>(A.nonZeros()));
  for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
    for (auto k = outer[j]; k < outer[j + 1]; ++k) {
      const auto i = inner[k];
      const auto* begin = inner + outer[i];
      const auto* end = inner + outer[i + 1];
      const auto* found = std::lower_bound(begin, end, static_cast<int>(j));
      if (found == end || *found != j) return {};
      slots[static_cast<std::size_t>(k)] = static_cast<int>(found - inner);
    }
  }
  return slots;
}

bool same_pattern_as(const SparseMatrix& A, const SparseMatrix& B) {
  return A.rows() == B.rows() && A.nonZeros() == B.nonZeros() &&
         std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1, B.outerIndexPtr()) &&
         std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), B.innerIndexPtr());
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

void StepSolver::take_pattern(const SparseMatrix& A) {
  outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
  inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  ldlt_analysed_ = false;
  lu_analysed_ = false;
  cholesky_.reset();
  transposed_.clear();
  structurally_symmetric_ = false;
  if (choice_ != SolverChoice::kEigen &&
      (choice_ == SolverChoice::kCholmod || A.rows() >= kCholmodFromSize)) {
    transposed_ = transposed_slots(A);
    structurally_symmetric_ = A.rows() > 0 && !transposed_.empty();
  }
}

bool StepSolver::use_cholmod(const SparseMatrix&) const { return structurally_symmetric_; }

std::optional<Vector> StepSolver::solve(const SparseMatrix& A, const Vector& b,
                                        const DefiniteMatrix& definite) {
  ++statistics_.solves;
  if (!same_pattern(A)) take_pattern(A);
  if (use_cholmod(A)) return solve_cholmod(A, b, definite);
  return solve_eigen(A, b);
}

std::optional<Vector> StepSolver::solve_eigen(const SparseMatrix& A, const Vector& b) {
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
    ++statistics_.analyses;
  }
  ldlt_.factorize(A);
  ++statistics_.factorizations;
  if (ldlt_.info() != Eigen::Success) return std::nullopt;
  Vector x = ldlt_.solve(b);
  return x;
}

std::optional<Vector> StepSolver::solve_lu(const SparseMatrix& A, const Vector& b) {
  if (!lu_analysed_) {
    lu_.analyzePattern(A);
    lu_analysed_ = true;
    ++statistics_.analyses;
  }
  lu_.factorize(A);
  ++statistics_.factorizations;
  if (lu_.info() != Eigen::Success) return std::nullopt;
  Vector x = lu_.solve(b);
  if (!x.allFinite()) return std::nullopt;
  return x;
}

void StepSolver::symmetrize(const SparseMatrix& M) {
  if (!same_pattern_as(preconditioner_, M)) preconditioner_ = M;
  const double* value = M.valuePtr();
  double* out = preconditioner_.valuePtr();
  for (std::size_t k = 0; k < transposed_.size(); ++k) {
    out[k] = 0.5 * (value[k] + value[transposed_[k]]);
  }
}

bool StepSolver::refactor(const SparseMatrix& A, const DefiniteMatrix& definite) {
  ++statistics_.factorizations;
  refactor_due_ = false;
  charged_ = 0.0;
  first_after_factor_ = true;
  bool ok = false;
  if (symmetric_) {
    ok = cholesky_->factorize(A);
  } else {
    symmetrize(A);
    ok = cholesky_->factorize(preconditioner_);
  }
  if (!ok && definite) {
    const SparseMatrix& D = definite();
    if (same_pattern_as(A, D)) {
      ++statistics_.definite_fallbacks;
      ++statistics_.factorizations;
      symmetrize(D);
      ok = cholesky_->factorize(preconditioner_);
    }
  }
  const double weight = cholesky_->is_supernodal() ? kSupernodalFlopWeight : kSimplicialFlopWeight;
  factor_cost_ = weight * cholesky_->factor_flops();
  iteration_cost_ = 4.0 * cholesky_->factor_nonzeros() + 2.0 * static_cast<double>(A.nonZeros());
  return ok;
}

std::optional<Vector> StepSolver::solve_cholmod(const SparseMatrix& A, const Vector& b,
                                                const DefiniteMatrix& definite) {
  if (!cholesky_) {
    cholesky_.emplace(CholeskyOptions{});
    cholesky_->analyze(A);
    ++statistics_.analyses;
    refactor_due_ = true;
  }
  const auto precondition = [this](const double* r, double* z) { cholesky_->solve(r, z, 1); };
  const double a_norm = A.norm();
  bool fresh = refactor_due_;
  for (;;) {
    if (fresh && !refactor(A, definite)) break;
    Vector x = cholesky_->solve(b);
    if (!x.allFinite()) break;
    const double tolerance = kResidualTolerance * (b.norm() + a_norm * x.norm());
    // A kept factor may take as many more iterations than a fresh one as a factorization
    // costs; a fresh one as many as GMRES keeps.
    const double affordable = std::clamp(factor_cost_ / std::max(iteration_cost_, 1.0), 2.0,
                                         static_cast<double>(kMaxKrylovIterations));
    const int most =
        fresh ? kMaxKrylovIterations
              : std::min(kMaxKrylovIterations, fresh_iterations_ + static_cast<int>(affordable));
    const KrylovResult result = gmres_.solve(A, b, x, precondition, tolerance, most);
    statistics_.krylov_iterations += result.iterations;
    if (result.converged && x.allFinite()) {
      if (first_after_factor_) {
        fresh_iterations_ = result.iterations;
        first_after_factor_ = false;
      } else {
        charged_ += std::max(0, result.iterations - fresh_iterations_) * iteration_cost_;
        refactor_due_ = charged_ >= factor_cost_;
      }
      last_ = Factorization::kCholesky;
      return x;
    }
    if (fresh) break;
    fresh = true;  // the kept factor no longer helps: factor A now and try once more
  }
  // Neither A, nor its symmetric part, nor the definite matrix made a factor that GMRES could
  // use: an LU (or LDLᵀ) of A itself, and a fresh try with CHOLMOD at the next solve.
  ++statistics_.direct_fallbacks;
  refactor_due_ = true;
  return solve_eigen(A, b);
}

}  // namespace fosssim
