#pragma once

#include <optional>

#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"
#include "core/systems/backward_euler.h"
#include "core/systems/step_matrix.h"

namespace fosssim {

/// Which step matrix gives Newton's directions when every force is conservative (the option
/// "hessian" of the "newton" integrator).
enum class NewtonHessian {
  /// A_θ = (1 - θ) A + θ Ā between the exact matrix A and the projected one Ā, θ adapted by the
  /// line search (see Newton).
  kAdaptive,
  /// Always Ā: projected Newton, every direction descends, convergence only linear where the
  /// projection changes the Hessian.
  kProjected,
  /// Always A, and Ā where A's direction climbs.
  kExact,
};

/// Settings of the "newton" integrator.
struct NewtonOptions {
  /// Stop once a correction is this small relative to the new velocities:
  /// ‖Δ‖∞ ≤ tolerance · max(‖vⁿ⁺¹‖∞, 1e-3 m/s).
  double tolerance = 1e-10;
  int max_iterations = 200;  ///< a step that has not converged by then fails (StepError)
  SolverChoice solver = SolverChoice::kAuto;
  NewtonHessian hessian = NewtonHessian::kAdaptive;
};

/// Backward Euler solved by Newton's method to round-off, for meshes: the accurate reference
/// the faster mesh integrators are measured against. The equations are BackwardEulerStep's
/// (core/systems/backward_euler.h), in the velocity change dv; each iteration solves
///   A Δ = r(dv),  A = M + h² hessX + h hessV at (qⁿ + h(vⁿ + dv), vⁿ + dv),
/// over the free degrees of freedom only (fixed particles eliminated: they keep their
/// velocity), with StepSolver (MUMPS or CHOLMOD with reused factors on large meshes), then
/// takes a step along Δ chosen by a backtracking line search from the first iteration on.
///
/// When every force is conservative the step minimizes the incremental potential Φ and the
/// line search asks Φ to decrease (Armijo). A compressed spring makes A indefinite, and on a
/// crumpling cloth A's direction often climbs, or descends only a tiny step; the projected
/// matrix Ā (every element's hessX projected to be semi-definite, StepMatrix::
/// assemble_definite) always gives a descent direction but converges only linearly where the
/// projection matters (projected Newton, as in Teran et al. 2005 and IPC, Li et al. 2020). By
/// default each iteration solves with the blend A_θ = (1 - θ) A + θ Ā ⪰ A, a trust-region-like
/// damping aimed at the elements that make A indefinite: θ starts at 1 every step, falls
/// by 3× after each step the line search takes at least half of (to 0 below 0.01, where the
/// convergence is Newton's, quadratic), rises by 3× after a shorter one, and where A_θ's
/// direction climbs it rises and the system is solved again. On the 58×58 and 81×81 cloths of
/// bench_implicit this halves the iterations of the exact matrix with fallback (docs/solvers.md).
/// Otherwise (damping, vortices: no potential) Δ is A's direction and the line search is on
/// ‖r‖². Either way the step ends where r = 0: the same implicit Euler step, to the tolerance.
///
/// It differs from the course's "implicit-euler" (ImplicitEuler), which keeps fixed particles
/// as identity rows, stops at an absolute 1e-9, and searches lines only when plain Newton fails.
class Newton final : public Integrator {
 public:
  explicit Newton(NewtonOptions options) : options_(options) {}

  /// Newton iterations taken by the last step.
  int last_iterations() const { return last_iterations_; }
  /// The linear solver and what it did so far.
  const StepSolver& solver() const { return *solver_; }
  SolverReport solver_report() const override {
    return {.iterations_of = "newton",
            .last_step_iterations = last_iterations_,
            .linear_solves = solver_ ? std::optional(solver_->statistics()) : std::nullopt};
  }

 protected:
  void prepare() override;
  void advance(State& state) override;

 private:
  /// A_θ = (1 - θ) A + θ Ā in blended_: its values written in place when A and Ā share a
  /// pattern (StepMatrix scatters both into the same slots), so no iteration allocates.
  const SparseMatrix& blend_matrices(const SparseMatrix& exact, const SparseMatrix& projected,
                                     double theta);
  /// Solves A Δ = rhs over the free DOFs; Δ full size. `step`: for the error message.
  Vector solve(const SparseMatrix& A, const Vector& rhs, int step);
  /// One step when every force is conservative: minimizes Φ. Returns dv.
  Vector minimize(const BackwardEulerStep& problem);
  /// One step of forces without a potential: decreases ‖r‖². Returns dv.
  Vector find_root(const BackwardEulerStep& problem);
  /// Whether a correction of dv by `step` ends the iterations (then dv is the answer).
  bool converged(const State& state, const Vector& dv, const Vector& step);
  [[noreturn]] void fail(const State& state) const;

  NewtonOptions options_;
  std::optional<StepMatrix> matrix_;
  std::optional<StepSolver> solver_;
  SparseMatrix blended_;  // A_θ for 0 < θ < 1
  double last_correction_ = 0.0;
  int last_iterations_ = 0;
};

/// Registry entry: "newton". Options: tolerance, max-iterations, solver, hessian.
extern const IntegratorMethod kNewtonMethod;

}  // namespace fosssim
