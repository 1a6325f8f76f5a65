#include "core/integrators/linearized_implicit_euler.h"

#include "core/force_evaluation.h"
#include "core/step_error.h"

namespace fosssim {

void LinearizedImplicitEuler::advance(const SceneModel& model, State& state) {
  const double h = model.integrator.dt;
  const Vector predicted_q = state.q + h * state.v;
  Vector rhs = h * compute_force(model, predicted_q, state.v);
  zero_fixed(model, rhs);
  const SparseMatrix A = assemble_step_matrix(model, predicted_q, state.v, h, scratch_);
  const auto dv = solver_.solve(A, rhs);
  if (!dv)
    throw StepError(state.step + 1, "linearized implicit Euler: the step matrix is singular");
  state.v += *dv;
  state.q += h * state.v;
}

}  // namespace fosssim
