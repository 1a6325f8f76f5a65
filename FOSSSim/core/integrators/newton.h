#pragma once

#include <optional>

#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"
#include "core/systems/backward_euler.h"
#include "core/systems/step_matrix.h"

namespace fosssim {

/// Settings of the "newton" integrator.
struct NewtonOptions {
  /// Stop once a correction is this small relative to the new velocities:
  /// ‖Δ‖∞ ≤ tolerance · max(‖vⁿ⁺¹‖∞, 1e-3 m/s).
  double tolerance = 1e-10;
  int max_iterations = 50;  ///< a step that has not converged by then fails (StepError)
  SolverChoice solver = SolverChoice::kAuto;
};

/// Backward Euler solved by Newton's method to round-off, for meshes: the accurate reference
/// the faster mesh integrators are measured against. The equations are BackwardEulerStep's
/// (core/systems/backward_euler.h), in the velocity change dv; each iteration solves
///   A Δ = r(dv),  A = M + h² hessX + h hessV at (qⁿ + h(vⁿ + dv), vⁿ + dv),
/// over the free degrees of freedom only (fixed particles eliminated: they keep their
/// velocity), with StepSolver (CHOLMOD with reused factors on large meshes), then takes a
/// step along Δ chosen by a backtracking line search from the first iteration on: on the
/// incremental potential when every force is conservative (Armijo; where a compressed spring
/// makes A indefinite and Δ climbs, the step matrix with projected spring Hessians gives the
/// direction instead), otherwise on ‖r‖². Near the solution full steps are taken and the
/// convergence is quadratic.
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

 protected:
  void prepare() override;
  void advance(State& state) override;

 private:
  /// The Newton direction at dv (full size), or the definite one when `definite`.
  Vector direction(const BackwardEulerStep& problem, const Vector& dv, const Vector& rhs,
                   bool definite);

  NewtonOptions options_;
  std::optional<StepMatrix> matrix_;
  std::optional<StepSolver> solver_;
  int last_iterations_ = 0;
};

/// Registry entry: "newton". Options: tolerance, max-iterations, solver.
extern const IntegratorMethod kNewtonMethod;

}  // namespace fosssim
