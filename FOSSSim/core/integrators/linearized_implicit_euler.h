#pragma once

#include <optional>

#include "core/integrators/integrator.h"
#include "core/solvers/step_solver.h"
#include "core/systems/step_matrix.h"

namespace fosssim {

/// One Newton step of implicit Euler, linearized at the predicted state, in the course's
/// update order (docs/integrators.md):
///   q* = qⁿ + h vⁿ;  A = M + h² hessX(q*, vⁿ) + h hessV(q*, vⁿ);  A δv = h F(q*, vⁿ)
///   with the course's identity rows for fixed particles;  vⁿ⁺¹ = vⁿ + δv;  qⁿ⁺¹ = qⁿ + h vⁿ⁺¹.
/// Small 2D systems are assembled and solved the course's way (StepMatrix::assemble_course,
/// CourseLu; uses_course_lu), bit for bit the course's steps; larger ones by StepSolver.
/// Baraff and Witkin, "Large steps in cloth simulation", SIGGRAPH 1998.
class LinearizedImplicitEuler final : public Integrator {
 public:
  explicit LinearizedImplicitEuler(SolverChoice solver = SolverChoice::kAuto) : choice_(solver) {}

  /// The linear solver and what it did so far.
  const StepSolver& solver() const { return *solver_; }
  SolverReport solver_report() const override {
    // The course's dense LU (small 2D systems) keeps no statistics.
    return {.linear_solves =
                solver_ && !course_ ? std::optional(solver_->statistics()) : std::nullopt};
  }

 protected:
  void prepare() override;
  void advance(State& state) override;

 private:
  SolverChoice choice_;
  bool course_ = false;  // the course's dense assembly and LU
  CourseLu course_lu_;
  std::optional<StepMatrix> matrix_;
  std::optional<StepSolver> solver_;
};

/// Registry entry: "linearized-implicit-euler", also "linearized-implicit". Option: solver.
extern const IntegratorMethod kLinearizedImplicitEulerMethod;

}  // namespace fosssim
