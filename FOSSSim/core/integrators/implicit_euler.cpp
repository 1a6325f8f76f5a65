#include "core/integrators/implicit_euler.h"

#include "core/force_evaluation.h"
#include "core/step_error.h"
#include "core/text.h"

namespace fosssim {

void ImplicitEuler::advance(const SceneModel& model, State& state) {
  const double h = model.integrator.dt;
  const NewtonSettings& newton = model.integrator.newton;
  Vector dv = Vector::Zero(state.v.size());
  Vector dx = h * state.v;
  double correction_norm = 0.0;
  for (int iteration = 1; iteration <= newton.max_iterations; ++iteration) {
    const Vector q = state.q + dx;
    const Vector v = state.v + dv;
    Vector rhs = h * compute_force(model, q, v) - model.mass.cwiseProduct(dv);
    zero_fixed(model, rhs);
    const SparseMatrix A = assemble_step_matrix(model, q, v, h, scratch_);
    const auto delta = solver_.solve(A, rhs);
    if (!delta) {
      throw StepError(state.step + 1, "implicit Euler: the Newton matrix is singular at iteration " +
                                          std::to_string(iteration));
    }
    dv += *delta;
    dx = h * (state.v + dv);
    correction_norm = delta->norm();
    if (correction_norm < newton.tolerance) {
      last_iterations_ = iteration;
      state.q += dx;
      state.v += dv;
      return;
    }
  }
  throw StepError(state.step + 1, "implicit Euler: Newton's method did not converge in " +
                                      std::to_string(newton.max_iterations) +
                                      " iterations (last correction norm " +
                                      to_text(correction_norm) + ", tolerance " +
                                      to_text(newton.tolerance) + ")");
}

}  // namespace fosssim
