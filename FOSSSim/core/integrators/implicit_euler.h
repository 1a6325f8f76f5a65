#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/hessian_builder.h"
#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"

namespace fosssim {

/// Backward Euler solved by Newton's method on the velocity change (SPEC section 4):
/// unknown dv = vⁿ⁺¹ - vⁿ, start dv = 0, dx = h vⁿ; repeat
///   rhs = h F(qⁿ + dx, vⁿ + dv) - M dv (fixed zeroed);  A Δ = rhs with A as in linearized
///   implicit Euler at (qⁿ + dx, vⁿ + dv);  dv += Δ;  dx = h (vⁿ + dv)
/// until ‖Δ‖₂ < tolerance (at least one iteration); then qⁿ⁺¹ = qⁿ + dx, vⁿ⁺¹ = vⁿ + dv.
///
/// This plain Newton iteration is the course's and is always tried first, so every step it
/// solves is bit-identical to the course's reference. Plain Newton is not globally convergent
/// (a stiff, strongly stretched spring system with a large step can make it wander); when it
/// does not converge within NewtonSettings::max_iterations, the step is solved again from
/// dv = 0 with a backtracking (Armijo) line search. When every force is conservative, backward
/// Euler is the minimization of the incremental potential Φ(dv) = ½ dvᵀM dv + U(qⁿ + h(vⁿ+dv))
/// (gradient -rhs, Hessian A), so the search minimizes Φ, stepping along M⁻¹rhs where an
/// indefinite A makes the Newton step climb; otherwise it reduces ‖rhs‖², for which the Newton
/// step is always a descent direction. Only if that fails too is StepError thrown. Steps that
/// needed the line search are counted (line_search_steps()).
class ImplicitEuler final : public Integrator {
 public:
  explicit ImplicitEuler(const SceneModel& model) : solver_(model.has_symmetric_jacobians()) {}

  /// Newton iterations taken by the last step (of the line-search solve, if it was needed).
  int last_iterations() const { return last_iterations_; }
  /// Number of steps so far that plain Newton could not solve and the line search did.
  std::int64_t line_search_steps() const { return line_search_steps_; }
  std::vector<std::string> notes() const override;

 protected:
  void advance(const SceneModel& model, State& state) override;

 private:
  struct NewtonResult {
    bool converged = false;
    int iterations = 0;
    double last_correction_norm = 0.0;
  };
  /// Runs Newton from dv = 0 on the step from `state`; dv receives the result.
  NewtonResult solve(const SceneModel& model, const State& state, bool line_search, Vector& dv);
  /// rhs(dv) = h F(qⁿ + h(vⁿ + dv), vⁿ + dv) - M dv with fixed DOFs zeroed.
  Vector residual(const SceneModel& model, const State& state, const Vector& dv) const;
  /// Φ(dv) = ½ dvᵀM dv + U(qⁿ + h(vⁿ + dv)), whose gradient is -rhs for conservative models.
  double incremental_potential(const SceneModel& model, const State& state, const Vector& dv) const;
  /// A step that decreases Φ enough (Armijo), along the Newton step or, failing descent, M⁻¹rhs.
  Vector descent_step(const SceneModel& model, const State& state, const Vector& dv,
                      const Vector& rhs, const Vector& newton_step) const;
  /// A fraction of the Newton step that decreases ‖rhs‖² enough (Armijo); rhs becomes the
  /// residual at dv plus that step.
  Vector residual_step(const SceneModel& model, const State& state, const Vector& dv, Vector& rhs,
                       const Vector& newton_step) const;

  StepSolver solver_;
  HessianBuilder scratch_;
  int last_iterations_ = 0;
  std::int64_t line_search_steps_ = 0;
};

}  // namespace fosssim
