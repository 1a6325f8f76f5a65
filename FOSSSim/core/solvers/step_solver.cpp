#include "core/solvers/step_solver.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

namespace {
#ifdef FOSSSIM_NO_SPARSE_DIRECT
/// A build without SuiteSparse and MUMPS (WebAssembly) keeps large systems on the Eigen path
/// too; only a scene that names the sparse direct solvers reaches their (refusing) classes.
constexpr bool kHaveSparseDirect = false;
#else
constexpr bool kHaveSparseDirect = true;
#endif
/// Accept a solution when its residual is this small relative to the system's scale.
constexpr double kResidualTolerance = 1e-12;
/// GMRES never keeps more directions than this; a factor that needs more is replaced.
constexpr int kMaxKrylovIterations = 30;
/// Operations of a numeric factorization are charged at this fraction of those of a solve:
/// dense supernodal and frontal blocks run near BLAS-3 speed, triangular sweeps at memory
/// speed (measured on the 81×81 cloth and the tet ball with OpenBLAS, bench_implicit).
constexpr double kBlockedFlopWeight = 0.2;
constexpr double kSimplicialFlopWeight = 1.0;
/// A factorization also costs this many operations per entry of its factor, whatever its
/// flops: assembling, copying and scattering fronts, which dominates small factors. Measured
/// with CHOLMOD's supernodal factor on the 2D damped cloth of bench_implicit: one factorization
/// costs 16, 14 and 12.5 GMRES iterations at 30×30, 100×100 and 316×316 (3·10⁶ to 6·10⁹
/// flops), where the flops alone charged 2, 5.6 and 14.7; this term makes it 10, 11 and 14.7.
constexpr double kFactorOperationsPerEntry = 50.0;
/// A double-precision factorization takes this many times a single one's time (MUMPS on the
/// step matrices of bench_implicit's 81×81 cloth, one BLAS thread: 56 to 62 ms in single
/// precision, about 100 ms in double; with GMRES to round-off, 76 against 122 ms a step).
constexpr double kSinglePrecisionSpeedup = 2.0;
/// After a Cholesky factorization fails (A is not positive definite), this many
/// factorizations go straight to LU before Cholesky is tried again.
constexpr int kLuAfterIndefinite = 4;
/// The longest run of solves that factor at once after kept factors failed (or that skip
/// multigrid after it missed).
constexpr int kLongestBackoff = 16;
/// Krylov iterations with BoomerAMG take 10 to 30 iterations on the step matrices measured
/// (bench_elastic); more means A is indefinite or too far from what multigrid handles.
constexpr int kMaxAmgIterations = 100;
/// A BoomerAMG setup costs about as much as this many Krylov iterations with its hierarchy
/// (bench_elastic --profile-amg: a setup is 26 to 30 V-cycles on the sheets of 10⁴ and 10⁵
/// triangles, an iteration a V-cycle and a product with A): a kept hierarchy is replaced once
/// the iterations it needed beyond a fresh one's have cost as much (the rent-or-buy rule of the
/// factors above).
constexpr double kAmgSetupIterations = 24.0;

/// The cost charged for a numeric factorization, in the operations GMRES iterations are counted in.
double factorization_cost(double flops, double factor_entries, double flop_weight) {
  return std::max(flop_weight * flops, kFactorOperationsPerEntry * factor_entries);
}

double residual_scale(const SparseMatrix& A, const Vector& x, const Vector& b) {
  return b.norm() + A.norm() * x.norm();
}

bool is_accurate(const SparseMatrix& A, const Vector& x, const Vector& b) {
  if (!x.allFinite()) return false;
  return (A * x - b).norm() <= kResidualTolerance * residual_scale(A, x, b);
}

}  // namespace

bool StepSolver::same_pattern(const SparseMatrix& A) const {
  // With a symmetric part, its pattern (half of A's) is the only copy kept.
  if (suitesparse_ && !symmetric_) return symmetric_part_.has_pattern(A);
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  return static_cast<Eigen::Index>(outer_.size()) == A.outerSize() + 1 &&
         static_cast<Eigen::Index>(inner_.size()) == A.nonZeros() &&
         std::equal(outer_.begin(), outer_.end(), outer) &&
         std::equal(inner_.begin(), inner_.end(), inner);
}

void StepSolver::take_pattern(const SparseMatrix& A) {
  ldlt_analysed_ = false;
  lu_analysed_ = false;
  cholesky_.reset();
  umfpack_.reset();
  mumps_.reset();
  ldlt_precision_ = FactorPrecision::kSingle;
  skip_cholesky_ = 0;
  refactor_due_ = true;
  suitesparse_ = false;
  amg_skip_ = 0;
  amg_skip_length_ = 0;
  // amg_available() loads hypre (and OpenMPI) the first time: asked only when multigrid is wanted.
  amg_ = A.rows() > 0 &&
         (choice_ == SolverChoice::kAmg ||
          (choice_ == SolverChoice::kAuto && !symmetric_ && A.rows() >= kAmgFromSize)) &&
         amg_available();
  if (choice_ != SolverChoice::kEigen && A.rows() > 0 &&
      (choice_ == SolverChoice::kSparseDirect ||
       (kHaveSparseDirect && A.rows() >= kSparseDirectFromSize))) {
    // A pattern that is not structurally symmetric has no symmetric part of its own pattern;
    // step matrices always are (pair blocks come in pairs).
    suitesparse_ = symmetric_ ? UpperSymmetricPart::is_structurally_symmetric(A)
                              : symmetric_part_.take_pattern(A);
  }
  if (suitesparse_ && !symmetric_) {
    outer_ = {};
    inner_ = {};
  } else {
    outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
    inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  }
}

std::optional<Vector> StepSolver::solve(const SparseMatrix& A, const Vector& b) {
  // A scene with no free degree of freedom (no particles, or only fixed ones) has nothing to
  // solve; Eigen's factorizations and norms assert on 0×0 matrices in Debug builds.
  if (A.rows() == 0) return Vector(0);
  ++statistics_.solves;
  if (!same_pattern(A)) take_pattern(A);
  if (amg_) {
    if (auto x = solve_amg(A, b)) return x;
  }
  if (suitesparse_) return solve_suitesparse(A, b);
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

bool StepSolver::factor_cholesky(const SparseMatrix& A) {
  // Only non-symmetric matrices come here (symmetric ones go to MUMPS): factor their
  // symmetric part, of which CHOLMOD reads the upper triangle.
  const SparseMatrix* target = &symmetric_part_.update(A);
  if (!cholesky_) {
    cholesky_.emplace(CholeskyOptions{.triangle = CholeskyOptions::Triangle::kUpper});
    cholesky_->analyze(*target);
    ++statistics_.analyses;
  }
  ++statistics_.factorizations;
  if (!cholesky_->factorize(*target)) return false;
  factor_ = Factorization::kCholesky;
  const double weight = cholesky_->is_supernodal() ? kBlockedFlopWeight : kSimplicialFlopWeight;
  factor_cost_ =
      factorization_cost(cholesky_->factor_flops(), cholesky_->factor_nonzeros(), weight);
  iteration_cost_ = 4.0 * cholesky_->factor_nonzeros() + 2.0 * static_cast<double>(A.nonZeros());
  return true;
}

bool StepSolver::factor_lu(const SparseMatrix& A) {
  if (!umfpack_) {
    umfpack_.emplace();
    umfpack_->analyze(A);
    ++statistics_.analyses;
  }
  ++statistics_.factorizations;
  ++statistics_.lu_factorizations;
  if (!umfpack_->factorize(A)) return false;
  factor_ = Factorization::kUmfpack;
  factor_cost_ =
      factorization_cost(umfpack_->factor_flops(), umfpack_->factor_nonzeros(), kBlockedFlopWeight);
  iteration_cost_ = 2.0 * umfpack_->factor_nonzeros() + 2.0 * static_cast<double>(A.nonZeros());
  return true;
}

bool StepSolver::factor_ldlt(const SparseMatrix& A) {
  if (!mumps_) {
    mumps_.emplace(ldlt_precision_);
    mumps_->analyze(A);
    ++statistics_.analyses;
  }
  ++statistics_.factorizations;
  ++statistics_.ldlt_factorizations;
  if (ldlt_precision_ == FactorPrecision::kSingle) ++statistics_.single_precision_factorizations;
  if (!mumps_->factorize(A)) {
    // Singular in single precision (or beyond its range) need not be singular in double.
    if (ldlt_precision_ == FactorPrecision::kDouble) return false;
    use_double_ldlt();
    return factor_ldlt(A);
  }
  factor_ = Factorization::kMumps;
  factor_cost_ =
      factorization_cost(mumps_->factor_flops(), mumps_->factor_nonzeros(), kBlockedFlopWeight);
  if (ldlt_precision_ == FactorPrecision::kSingle) factor_cost_ /= kSinglePrecisionSpeedup;
  iteration_cost_ = 4.0 * mumps_->factor_nonzeros() + 2.0 * static_cast<double>(A.nonZeros());
  return true;
}

void StepSolver::use_double_ldlt() {
  ldlt_precision_ = FactorPrecision::kDouble;
  mumps_.reset();
}

bool StepSolver::refactor(const SparseMatrix& A) {
  refactor_due_ = false;
  charged_ = 0.0;
  first_after_factor_ = true;
  if (symmetric_) return factor_ldlt(A);
  // Non-symmetric A (damped springs, vortices): a Cholesky factor of the symmetric part,
  // (A + Aᵀ)/2, preconditions at less cost than an LU factor of A (measured, bench_implicit).
  if (skip_cholesky_ == 0) {
    if (factor_cholesky(A)) return true;
    skip_cholesky_ = kLuAfterIndefinite;
  } else if (skip_cholesky_ > 0) {
    --skip_cholesky_;
  }
  return factor_lu(A);
}

void StepSolver::precondition(const double* r, double* z) const {
  if (factor_ == Factorization::kCholesky) {
    cholesky_->solve(r, z, 1);
  } else if (factor_ == Factorization::kMumps) {
    mumps_->solve(r, z);
  } else {
    umfpack_->solve(r, z);
  }
}

std::optional<Vector> StepSolver::solve_suitesparse(const SparseMatrix& A, const Vector& b) {
  const auto precondition = [this](const double* r, double* z) { this->precondition(r, z); };
  const double a_norm = A.norm();
  Vector x(b.size());
  bool fresh = refactor_due_ || backoff_ > 0;
  if (backoff_ > 0) --backoff_;
  for (;;) {
    if (fresh && !refactor(A)) break;
    // The residual asked for is round-off in the scale ‖b‖ + ‖A‖ ‖x‖ of the system. A fresh
    // factor gives ‖x‖; a kept one may be far from A, so the scale of the last answer is used.
    const double b_norm = b.norm();
    double tolerance = kResidualTolerance * b_norm * (1.0 + scale_ratio_);
    if (fresh) {
      // A fresh factor's M⁻¹b is a good start (a double factor's is often the answer).
      precondition(b.data(), x.data());
      tolerance = kResidualTolerance * (b_norm + a_norm * x.norm());
    } else {
      // From x = 0, GMRES's first iterate is the best multiple of M⁻¹b: never worse than b,
      // even when a kept factor is far from A.
      x.setZero();
    }
    // A kept factor may take as many more iterations than a fresh one as a factorization
    // costs; a fresh one as many as GMRES keeps.
    const double affordable = std::clamp(factor_cost_ / std::max(iteration_cost_, 1.0), 2.0,
                                         static_cast<double>(kMaxKrylovIterations));
    const int most =
        fresh ? kMaxKrylovIterations
              : std::min(kMaxKrylovIterations, fresh_iterations_ + static_cast<int>(affordable));
    // A kept factor that stops paying is dropped as soon as GMRES's rate shows it.
    const KrylovResult result = gmres_.solve(A, b, x, precondition, tolerance, most, !fresh);
    statistics_.krylov_iterations += result.iterations;
    const double x_norm = x.norm();
    if (result.converged && x.allFinite() &&
        result.residual <= kResidualTolerance * (b_norm + a_norm * x_norm)) {
      scale_ratio_ = b_norm > 0.0 ? a_norm * x_norm / b_norm : 0.0;
      if (first_after_factor_) {
        // Counted as a kept factor's solves are: its start M⁻¹b was one more solve with M.
        fresh_iterations_ = result.iterations + 1;
        first_after_factor_ = false;
      } else {
        backoff_length_ = 0;
        charged_ += std::max(0, result.iterations - fresh_iterations_) * iteration_cost_;
        refactor_due_ = charged_ >= factor_cost_;
      }
      last_ = factor_;
      return x;
    }
    if (fresh) {
      if (factor_ == Factorization::kMumps && ldlt_precision_ == FactorPrecision::kSingle) {
        // A fresh single-precision factor was too inexact for A's condition: from now on, and
        // at once, a double one.
        use_double_ldlt();
      } else if (factor_ == Factorization::kCholesky) {
        // A fresh factor of A's symmetric part did not help: an LU factor of A itself will.
        skip_cholesky_ = kLuAfterIndefinite;
      } else {
        break;
      }
    } else {
      backoff_length_ = std::clamp(2 * backoff_length_, 1, kLongestBackoff);
      backoff_ = backoff_length_;
    }
    fresh = true;  // the kept factor no longer helps: factor A now and try once more
  }
  // No factor GMRES could use: Eigen's LU (or LDLᵀ) of A itself, and a fresh factor next time.
  ++statistics_.direct_fallbacks;
  refactor_due_ = true;
  return solve_eigen(A, b);
}

std::optional<Vector> StepSolver::solve_amg(const SparseMatrix& A, const Vector& b) {
  if (amg_skip_ > 0) {
    --amg_skip_;
    return std::nullopt;
  }
  const double b_norm = b.norm();
  const double a_norm = A.norm();
  Vector x(b.size());
  bool fresh = !amg_solver_.ready() || amg_setup_due_;
  for (;;) {
    if (fresh) {
      ++statistics_.amg_setups;
      amg_setup_due_ = false;
      amg_charged_ = 0.0;
      if (!amg_solver_.setup(A, components_)) {
        amg_ = false;  // hypre cannot take this pattern (or MPI did not start): not again
        return std::nullopt;
      }
    } else if (symmetric_ && !amg_solver_.set_matrix(A)) {
      amg_ = false;
      return std::nullopt;
    }
    // A kept hierarchy may take as many iterations more than a fresh one as a setup costs.
    const int most = fresh ? kMaxAmgIterations
                           : std::min(kMaxAmgIterations,
                                      amg_fresh_iterations_ + static_cast<int>(kAmgSetupIterations));
    x.setZero();
    int iterations = 0;
    bool accurate = false;
    if (symmetric_) {
      // Hypre's CG stops at ‖r‖ ≤ tol ‖b‖; the promise is ‖r‖ ≤ 1e-12 (‖b‖ + ‖A‖ ‖x‖), in the
      // scale of the last answer (of this one's first iterate for the first solve). Its
      // recurrence may end a little above the true residual: then once more from there, asking
      // for a hundredth. The residual decides, not CG's own verdict.
      double ratio = scale_ratio_;
      double tolerance = kResidualTolerance * (1.0 + ratio);
      for (int attempt = 0; attempt < 3 && !accurate && iterations < most; ++attempt) {
        const KrylovResult result =
            amg_solver_.conjugate_gradients(b, x, tolerance, most - iterations);
        iterations += result.iterations;
        if (!x.allFinite()) break;
        accurate = is_accurate(A, x, b);
        if (!result.converged) break;
        const double new_ratio = b_norm > 0.0 ? a_norm * x.norm() / b_norm : 0.0;
        tolerance = new_ratio > ratio ? kResidualTolerance * (1.0 + new_ratio) : tolerance * 1e-2;
        ratio = std::max(ratio, new_ratio);
      }
      last_ = Factorization::kAmgCg;
    } else {
      const AmgSolver& amg = amg_solver_;
      const auto precondition = [&amg](const double* r, double* z) { amg.apply(r, z); };
      amg.apply(b.data(), x.data());  // M⁻¹ b, GMRES's start
      const double tolerance = kResidualTolerance * (b_norm + a_norm * x.norm());
      const KrylovResult result =
          gmres_.solve(A, b, x, precondition, tolerance, std::min(most, kMaxKrylovIterations), !fresh);
      iterations = result.iterations + 1;
      accurate = result.converged && is_accurate(A, x, b);
      last_ = Factorization::kAmgGmres;
    }
    statistics_.krylov_iterations += iterations;
    if (accurate) {
      if (fresh) {
        amg_fresh_iterations_ = iterations;
      } else {
        amg_charged_ += std::max(0, iterations - amg_fresh_iterations_);
        amg_setup_due_ = amg_charged_ >= kAmgSetupIterations;
      }
      amg_skip_length_ = 0;
      scale_ratio_ = b_norm > 0.0 ? a_norm * x.norm() / b_norm : 0.0;
      return x;
    }
    if (!fresh) {  // the kept hierarchy no longer helps: a new one, once more
      fresh = true;
      continue;
    }
    ++statistics_.amg_failures;
    amg_setup_due_ = true;
    amg_skip_length_ = std::clamp(2 * amg_skip_length_, 1, kLongestBackoff);
    amg_skip_ = amg_skip_length_;
    return std::nullopt;
  }
}

}  // namespace fosssim
