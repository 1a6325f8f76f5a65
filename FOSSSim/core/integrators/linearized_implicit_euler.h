#pragma once

#include "core/hessian_builder.h"
#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"

namespace fosssim {

/// One Newton step of implicit Euler, linearized at the predicted state (SPEC section 4):
///   q* = qⁿ + h vⁿ;  A = M + h² hessX(q*, vⁿ) + h hessV(q*, vⁿ);  A δv = h F(q*, vⁿ),
///   with fixed particles eliminated;  vⁿ⁺¹ = vⁿ + δv;  qⁿ⁺¹ = qⁿ + h vⁿ⁺¹.
/// Baraff and Witkin, "Large steps in cloth simulation", SIGGRAPH 1998.
class LinearizedImplicitEuler final : public Integrator {
 public:
  explicit LinearizedImplicitEuler(const SceneModel& model)
      : solver_(model.has_symmetric_jacobians()) {}

 protected:
  void advance(const SceneModel& model, State& state) override;

 private:
  StepSolver solver_;
  HessianBuilder scratch_;
};

}  // namespace fosssim
