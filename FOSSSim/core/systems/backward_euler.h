#pragma once
// Backward Euler's step as equations in the velocity change, and line searches on them.

#include "core/force_set.h"
#include "core/state.h"
#include "core/types.h"

namespace fosssim {

/// The backward Euler step from `start` over h, written in the unknown velocity change dv
/// (vⁿ⁺¹ = vⁿ + dv, qⁿ⁺¹ = qⁿ + h vⁿ⁺¹):
///   residual r(dv) = h F(qⁿ + h(vⁿ + dv), vⁿ + dv) - M dv, fixed DOFs zeroed; the step is a root;
///   incremental potential Φ(dv) = ½ dvᵀM dv + U(qⁿ + h(vⁿ + dv)).
/// When every force is conservative, -r is the gradient of Φ (over the free DOFs) and the step
/// minimizes Φ, so a line search can ask Φ to decrease (Martin et al., "Example-based elastic
/// materials", SIGGRAPH 2011; Gast et al., "Optimization integrator for large time steps",
/// TVCG 2015). Its Jacobian -dr/ddv is the step matrix A = M + h² hessX + h hessV.
struct BackwardEulerStep {
  const ForceSet& forces;
  const State& start;
  double h;

  /// r(dv).
  Vector residual(const Vector& dv) const;
  /// Φ(dv).
  double incremental_potential(const Vector& dv) const;
};

/// A step along `direction` from dv that decreases Φ enough (Armijo's rule with backtracking
/// by halves), where rhs = r(dv). When `direction` does not descend (an indefinite A can make
/// the Newton step climb), the mass-scaled steepest descent direction M⁻¹ r is used instead.
/// Returns the step to add to dv. `potential`, when given, holds Φ(dv) on entry (or NaN when
/// it is not known) and Φ(dv + step) on return, which spares an iterative caller one
/// evaluation of Φ per step. `fraction`, when given, receives the accepted fraction α of the
/// direction (1: the full step; of M⁻¹ r when `direction` climbed).
Vector potential_line_search(const BackwardEulerStep& problem, const Vector& dv, const Vector& rhs,
                             const Vector& direction, double* potential = nullptr,
                             double* fraction = nullptr);

/// A fraction of the Newton step `newton_step` from dv that decreases ½‖r‖² enough (Armijo; the
/// Newton step always descends on it), for forces without a potential. rhs = r(dv) on entry
/// and r(dv + step) on return. Returns the step to add to dv.
Vector residual_line_search(const BackwardEulerStep& problem, const Vector& dv, Vector& rhs,
                            const Vector& newton_step);

}  // namespace fosssim
