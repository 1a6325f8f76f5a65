#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"
#include "core/systems/backward_euler.h"
#include "core/systems/step_matrix.h"

namespace fosssim {

/// Settings of Newton's method in implicit Euler.
struct NewtonSettings {
  double tolerance = 1e-9;   ///< stop when the L2 norm of a correction is below this (course)
  int max_iterations = 200;  ///< give up and report non-convergence after this many
  SolverChoice solver = SolverChoice::kAuto;  ///< how the Newton systems are solved
};

/// Backward Euler solved by Newton's method on the velocity change, in the course's update
/// order (docs/integrators.md): unknown dv = vⁿ⁺¹ - vⁿ, start dv = 0, dx = h vⁿ; repeat
///   rhs = h F(qⁿ + dx, vⁿ + dv) - M dv (fixed zeroed);  A Δ = rhs with A as in linearized
///   implicit Euler at (qⁿ + dx, vⁿ + dv);  dv += Δ;  dx = h (vⁿ + dv)
/// until ‖Δ‖₂ < tolerance (at least one iteration); then qⁿ⁺¹ = qⁿ + dx, vⁿ⁺¹ = vⁿ + dv.
/// The equations are those of BackwardEulerStep (core/systems/backward_euler.h).
///
/// This plain Newton iteration is the course's and is always tried first, so every step it
/// solves is bit-identical to the course's reference. Plain Newton is not globally convergent
/// (a stiff, strongly stretched spring system with a large step can make it wander); when it
/// does not converge within NewtonSettings::max_iterations, the step is solved again from
/// dv = 0 with a backtracking line search: on the incremental potential when every force is
/// conservative (potential_line_search), otherwise on ‖rhs‖² (residual_line_search). Only if
/// that fails too is StepError thrown. Steps that needed the line search are counted
/// (line_search_steps()).
class ImplicitEuler final : public Integrator {
 public:
  explicit ImplicitEuler(NewtonSettings settings) : settings_(settings) {}

  /// Newton iterations taken by the last step (of the line-search solve, if it was needed).
  int last_iterations() const { return last_iterations_; }
  /// Number of steps so far that plain Newton could not solve and the line search did.
  std::int64_t line_search_steps() const { return line_search_steps_; }
  std::vector<std::string> notes() const override;
  SolverReport solver_report() const override;
  /// The linear solver and what it did so far.
  const StepSolver& solver() const { return *solver_; }

 protected:
  void prepare() override;
  void advance(State& state) override;

 private:
  struct NewtonResult {
    bool converged = false;
    int iterations = 0;
    double last_correction_norm = 0.0;
  };
  /// The Newton correction: A Δ = rhs with A at (q, v); nullopt when A is singular.
  std::optional<Vector> correction(const Vector& q, const Vector& v, double h, const Vector& rhs);
  /// Runs Newton from dv = 0 on `problem`; dv receives the result.
  NewtonResult solve(const BackwardEulerStep& problem, bool line_search, Vector& dv);

  NewtonSettings settings_;
  bool course_ = false;  // the course's dense assembly, LU and norm
  CourseLu course_lu_;
  std::optional<StepMatrix> matrix_;
  std::optional<StepSolver> solver_;
  int last_iterations_ = 0;
  std::int64_t line_search_steps_ = 0;
};

/// Registry entry: "implicit-euler", also "implicit". Options: newton-tolerance,
/// newton-max-iterations, solver.
extern const IntegratorMethod kImplicitEulerMethod;

}  // namespace fosssim
