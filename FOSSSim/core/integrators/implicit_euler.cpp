#include "core/integrators/implicit_euler.h"

#include <cmath>

#include "core/force_evaluation.h"
#include "core/step_error.h"
#include "core/text.h"

namespace fosssim {

namespace {
/// Armijo constant of the line search: accept αΔ when ‖rhs‖² falls by at least 2cα of itself.
constexpr double kArmijo = 1e-4;
/// Give up halving the step below this fraction of the Newton step.
constexpr double kSmallestStep = 1e-10;
}  // namespace

Vector ImplicitEuler::residual(const SceneModel& model, const State& state,
                               const Vector& dv) const {
  const double h = model.integrator.dt;
  const Vector v = state.v + dv;
  const Vector q = state.q + h * v;
  Vector rhs = h * compute_force(model, q, v) - model.mass.cwiseProduct(dv);
  zero_fixed(model, rhs);
  return rhs;
}

double ImplicitEuler::incremental_potential(const SceneModel& model, const State& state,
                                            const Vector& dv) const {
  const double h = model.integrator.dt;
  const Vector v = state.v + dv;
  return 0.5 * dv.dot(model.mass.cwiseProduct(dv)) +
         compute_potential_energy(model, state.q + h * v, v);
}

ImplicitEuler::NewtonResult ImplicitEuler::solve(const SceneModel& model, const State& state,
                                                 bool line_search, Vector& dv) {
  const double h = model.integrator.dt;
  const NewtonSettings& newton = model.integrator.newton;
  const bool minimize = line_search && model.is_conservative();
  NewtonResult result;
  dv = Vector::Zero(state.v.size());
  Vector rhs = residual(model, state, dv);
  for (int iteration = 1; iteration <= newton.max_iterations; ++iteration) {
    const Vector v = state.v + dv;
    const SparseMatrix A = assemble_step_matrix(model, state.q + h * v, v, h, scratch_);
    const auto delta = solver_.solve(A, rhs);
    if (!delta) {
      throw StepError(state.step + 1,
                      "implicit Euler: the Newton matrix is singular at iteration " +
                          std::to_string(iteration));
    }
    result.iterations = iteration;
    result.last_correction_norm = delta->norm();
    if (result.last_correction_norm < newton.tolerance) {
      dv += *delta;
      result.converged = true;
      return result;
    }
    if (!line_search) {
      dv += *delta;
      rhs = residual(model, state, dv);
    } else if (minimize) {
      dv += descent_step(model, state, dv, rhs, *delta);
      rhs = residual(model, state, dv);
    } else {
      dv += residual_step(model, state, dv, rhs, *delta);  // updates rhs
    }
  }
  return result;
}

Vector ImplicitEuler::descent_step(const SceneModel& model, const State& state, const Vector& dv,
                                   const Vector& rhs, const Vector& newton_step) const {
  // -rhs is the gradient of Φ. Where A is indefinite the Newton step may climb; then step along
  // the mass-scaled steepest descent direction M⁻¹ rhs instead.
  Vector direction = newton_step;
  double slope = -rhs.dot(direction);
  if (!(slope < 0.0)) {
    direction = rhs.cwiseQuotient(model.mass);
    slope = -rhs.dot(direction);
  }
  const double start = incremental_potential(model, state, dv);
  // Φ is a difference of large energies near convergence; allow for its round-off.
  const double noise = 1e-13 * (std::abs(start) + 1.0);
  double alpha = 1.0;
  while (incremental_potential(model, state, dv + alpha * direction) >
             start + kArmijo * alpha * slope + noise &&
         alpha > kSmallestStep) {
    alpha *= 0.5;
  }
  return alpha * direction;
}

Vector ImplicitEuler::residual_step(const SceneModel& model, const State& state, const Vector& dv,
                                    Vector& rhs, const Vector& newton_step) const {
  // The Newton step is a descent direction for ½‖rhs‖², whose slope along it is -‖rhs‖².
  const double merit = rhs.squaredNorm();
  double alpha = 1.0;
  Vector trial = residual(model, state, dv + newton_step);
  while (trial.squaredNorm() > (1.0 - 2.0 * kArmijo * alpha) * merit && alpha > kSmallestStep) {
    alpha *= 0.5;
    trial = residual(model, state, dv + alpha * newton_step);
  }
  rhs = std::move(trial);
  return alpha * newton_step;
}

void ImplicitEuler::advance(const SceneModel& model, State& state) {
  const double h = model.integrator.dt;
  Vector dv;
  const NewtonResult plain = solve(model, state, /*line_search=*/false, dv);
  NewtonResult result = plain;
  if (!plain.converged) {
    result = solve(model, state, /*line_search=*/true, dv);
    if (!result.converged) {
      const NewtonSettings& newton = model.integrator.newton;
      throw StepError(state.step + 1, "implicit Euler: Newton's method did not converge in " +
                                          std::to_string(newton.max_iterations) +
                                          " iterations (last correction norm " +
                                          to_text(plain.last_correction_norm) + ", tolerance " +
                                          to_text(newton.tolerance) +
                                          "), nor with a line search (last correction norm " +
                                          to_text(result.last_correction_norm) +
                                          "); try a smaller time step or --newton-max-iterations");
    }
    ++line_search_steps_;
  }
  last_iterations_ = result.iterations;
  const Vector dx = h * (state.v + dv);
  state.q += dx;
  state.v += dv;
}

std::vector<std::string> ImplicitEuler::notes() const {
  if (line_search_steps_ == 0) return {};
  return {"implicit Euler: plain Newton did not converge on " + std::to_string(line_search_steps_) +
          " step(s); they were solved with a line search and may differ from the course's "
          "reference, which has no line search"};
}

}  // namespace fosssim
