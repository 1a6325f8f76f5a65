#include "core/integrators/newton.h"

#include <algorithm>
#include <array>
#include <string_view>

#include "core/integrators/solver_option.h"
#include "core/step_error.h"
#include "core/text.h"

namespace fosssim {

void Newton::prepare() {
  matrix_.emplace(forces(), FixedParticleRule::kElimination);
  solver_.emplace(forces().has_symmetric_jacobians(), options_.solver);
}

Vector Newton::direction(const BackwardEulerStep& problem, const Vector& dv, const Vector& rhs,
                         bool definite) {
  const double h = problem.h;
  const Vector v = problem.start.v + dv;
  const Vector q = problem.start.q + h * v;
  const SparseMatrix& A =
      definite ? matrix_->assemble_definite(q, v, h) : matrix_->assemble(q, v, h);
  const auto delta = solver_->solve(A, matrix_->restrict(rhs));
  if (!delta) {
    throw StepError(problem.start.step + 1, "newton: the step matrix is singular");
  }
  Vector full = Vector::Zero(dv.size());
  matrix_->add_solution(*delta, full);
  return full;
}

void Newton::advance(State& state) {
  const double h = model().integrator.dt;
  const BackwardEulerStep problem{forces(), state, h};
  const bool minimize = forces().is_conservative();
  Vector dv = Vector::Zero(state.v.size());
  Vector rhs = problem.residual(dv);
  double correction = 0.0;
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    Vector delta = direction(problem, dv, rhs, false);
    Vector step;
    if (minimize) {
      // -rhs is the gradient of the incremental potential: Δ must descend on it.
      if (rhs.dot(delta) <= 0.0 && rhs.squaredNorm() > 0.0) {
        delta = direction(problem, dv, rhs, true);
      }
      step = potential_line_search(problem, dv, rhs, delta);
      dv += step;
      rhs = problem.residual(dv);
    } else {
      step = residual_line_search(problem, dv, rhs, delta);  // updates rhs
      dv += step;
    }
    last_iterations_ = iteration;
    correction = step.lpNorm<Eigen::Infinity>();
    const double scale = std::max((state.v + dv).lpNorm<Eigen::Infinity>(), 1e-3);
    if (correction <= options_.tolerance * scale) {
      state.q += h * (state.v + dv);
      state.v += dv;
      return;
    }
  }
  throw StepError(state.step + 1, "newton: no convergence in " +
                                      std::to_string(options_.max_iterations) +
                                      " iterations (last correction " + to_text(correction) +
                                      " m/s); try a smaller time step or a larger max-iterations");
}

namespace {
constexpr NewtonOptions kDefaults;
constexpr std::array kOptions = {
    OptionSpec::number("tolerance", kDefaults.tolerance, 0.0, /*excluded=*/true,
                       "stop once a correction is this small relative to the velocities"),
    OptionSpec::integer("max-iterations", kDefaults.max_iterations, 1, 1000000,
                        "a step that has not converged after this many iterations fails"),
    kSolverOption,
};
}  // namespace

constinit const IntegratorMethod kNewtonMethod{
    .name = "newton",
    .aliases = {},
    .summary =
        "implicit Euler solved to round-off by Newton's method with line searches, "
        "fixed particles eliminated (the reference for meshes)",
    .options = kOptions,
    .properties = {.order = 1, .implicit = true, .energy = EnergyTrend::kDecays},
    .create = [](const OptionValues& options, int) -> std::unique_ptr<Integrator> {
      return std::make_unique<Newton>(NewtonOptions{
          options.number("tolerance"), options.integer("max-iterations"), solver_choice(options)});
    },
};

}  // namespace fosssim
