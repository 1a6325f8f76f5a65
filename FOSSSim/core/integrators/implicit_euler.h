#pragma once

#include "core/hessian_builder.h"
#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"

namespace fosssim {

/// Backward Euler solved by Newton's method on the velocity change (SPEC section 4):
/// unknown dv = vⁿ⁺¹ - vⁿ, start dv = 0, dx = h vⁿ; repeat
///   rhs = h F(qⁿ + dx, vⁿ + dv) - M dv (fixed zeroed);  A Δ = rhs with A as in linearized
///   implicit Euler at (qⁿ + dx, vⁿ + dv);  dv += Δ;  dx = h (vⁿ + dv)
/// until ‖Δ‖₂ < tolerance (at least one iteration); then qⁿ⁺¹ = qⁿ + dx, vⁿ⁺¹ = vⁿ + dv.
/// Throws StepError after NewtonSettings::max_iterations without convergence.
class ImplicitEuler final : public Integrator {
 public:
  explicit ImplicitEuler(const SceneModel& model) : solver_(model.has_symmetric_jacobians()) {}

  /// Newton iterations taken by the last step.
  int last_iterations() const { return last_iterations_; }

 protected:
  void advance(const SceneModel& model, State& state) override;

 private:
  StepSolver solver_;
  HessianBuilder scratch_;
  int last_iterations_ = 0;
};

}  // namespace fosssim
