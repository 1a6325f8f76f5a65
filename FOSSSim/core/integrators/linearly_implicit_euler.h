#pragma once

#include <optional>

#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"
#include "core/systems/step_matrix.h"

namespace fosssim {

/// One linearized step of implicit Euler at the current state, with fixed particles
/// eliminated, as in the CSC417 mass-spring assignment ("linearly implicit Euler",
/// docs/scenes-3d.md):
///   (M - h² K - h D) v⁺ = M v + h f(q, v) - h D v,  q⁺ = q + h v⁺,
/// with K = dF/dq = -hessX and D = dF/dv = -hessV at (qⁿ, vⁿ); without damping this is the
/// assignment's (M - h²K) v⁺ = M v + h f(q). It is solved for δv = v⁺ - v as
///   A δv = h F(q, v) - h² hessX v,  A = M + h² hessX + h hessV,
/// over the free degrees of freedom only (FixedParticleRule::kElimination). Fixed particles
/// keep their velocity (usually zero, so they stay exactly in place).
///
/// This differs from the course's LinearizedImplicitEuler, which linearizes at the predicted
/// position qⁿ + h vⁿ; both are first order and agree to O(h²) per step.
/// A compressed spring's Hessian is indefinite, so A may be too: the solve is a sparse LDLᵀ
/// accepted only with a round-off-level residual, else sparse LU (StepSolver). With the option
/// hessian="projected", element Hessians (springs, CST triangles, bending hinges) are projected
/// onto the positive semi-definite matrices first, which keeps A positive definite at the price of a less exact linearization
/// under compression.
class LinearlyImplicitEuler final : public Integrator {
 public:
  /// project_hessian: ask forces for semi-definite hessX blocks (ForceInput::definite_hessian).
  explicit LinearlyImplicitEuler(bool project_hessian, SolverChoice solver = SolverChoice::kAuto)
      : project_hessian_(project_hessian), choice_(solver) {}

  /// The factorization used by the last step.
  Factorization last_factorization() const { return solver_->last_factorization(); }
  /// The linear solver and what it did so far.
  const StepSolver& solver() const { return *solver_; }
  SolverReport solver_report() const override {
    return {.linear_solves = solver_ ? std::optional(solver_->statistics()) : std::nullopt};
  }

 protected:
  void prepare() override;
  void advance(State& state) override;

 private:
  bool project_hessian_;
  SolverChoice choice_;
  std::optional<StepMatrix> matrix_;
  std::optional<StepSolver> solver_;
};

/// Registry entry: "linearly-implicit-euler". Options: hessian (exact, projected), solver.
extern const IntegratorMethod kLinearlyImplicitEulerMethod;

}  // namespace fosssim
