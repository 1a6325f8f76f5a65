#pragma once

#include <vector>

#include "core/hessian_builder.h"
#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"

namespace fosssim {

/// One linearized step of implicit Euler at the current state, with fixed particles projected
/// out, as in the CSC417 mass-spring assignment ("linearly implicit Euler"):
///   (M - h² K - h D) v⁺ = M v + h f(q, v) - h D v,  q⁺ = q + h v⁺,
/// with K = dF/dq = -hessX and D = dF/dv = -hessV at (qⁿ, vⁿ); without damping this is the
/// assignment's (M - h²K) v⁺ = M v + h f(q). It is solved for δv = v⁺ - v as
///   A δv = h F(q, v) - h² hessX v,  A = M + h² hessX + h hessV,
/// over the free degrees of freedom only: with the selection P of the free DOFs,
/// q = Pᵀ q̂ + q_fixed, the system is P A Pᵀ δv̂ = P rhs, smaller than the compat "zero the
/// rows and columns, 1 on the diagonal" system. Fixed particles keep their velocity (usually
/// zero, so they stay exactly in place).
///
/// This differs from the compat LinearizedImplicitEuler, which linearizes at the predicted
/// position qⁿ + h vⁿ; both are first order and agree to O(h²) per step.
/// A compressed spring's Hessian is indefinite, so A may be too: the solve is a sparse LDLᵀ
/// accepted only with a round-off-level residual, else sparse LU (StepSolver). With
/// LinearlyImplicitSettings::project_hessian, spring Hessians are projected onto the positive
/// semi-definite matrices first, which keeps A positive definite at the price of a less exact
/// linearization under compression.
class LinearlyImplicitEuler final : public Integrator {
 public:
  explicit LinearlyImplicitEuler(const SceneModel& model);

  /// The factorization used by the last step.
  Factorization last_factorization() const { return solver_.last_factorization(); }

 protected:
  void advance(const SceneModel& model, State& state) override;

 private:
  StepSolver solver_;
  HessianBuilder scratch_;
  std::vector<int> free_dof_;  // DOF -> index among free DOFs, or -1
  int num_free_ = 0;
};

}  // namespace fosssim
