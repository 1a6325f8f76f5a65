#include "core/integrators/implicit_euler.h"

#include <array>
#include <string_view>

#include "core/integrators/solver_option.h"
#include "core/step_error.h"
#include "core/text.h"

namespace fosssim {

void ImplicitEuler::prepare() {
  matrix_.emplace(forces(), FixedParticleRule::kIdentityRows);
  solver_.emplace(forces().has_symmetric_jacobians(), settings_.solver, model().dim);
  course_ = uses_course_lu(settings_.solver, model().dim, matrix_->size());
}

std::optional<Vector> ImplicitEuler::correction(const Vector& q, const Vector& v, double h,
                                                const Vector& rhs) {
  if (!course_) return solver_->solve(matrix_->assemble(q, v, h), rhs);
  if (!course_lu_.factor(matrix_->assemble_course(q, v, h))) return std::nullopt;
  return course_lu_.solve(rhs);
}

ImplicitEuler::NewtonResult ImplicitEuler::solve(const BackwardEulerStep& problem, bool line_search,
                                                 Vector& dv) {
  const double h = problem.h;
  const State& state = problem.start;
  const bool minimize = line_search && forces().is_conservative();
  NewtonResult result;
  dv = Vector::Zero(state.v.size());
  Vector rhs = problem.residual(dv);
  for (int iteration = 1; iteration <= settings_.max_iterations; ++iteration) {
    cancellation().check();
    const Vector v = state.v + dv;
    const auto delta = correction(state.q + h * v, v, h, rhs);
    if (!delta) {
      throw StepError(state.step + 1,
                      "implicit Euler: the Newton matrix is singular at iteration " +
                          std::to_string(iteration));
    }
    result.iterations = iteration;
    result.last_correction_norm = course_ ? two_lane_norm(*delta) : delta->norm();
    if (result.last_correction_norm < settings_.tolerance) {
      dv += *delta;
      result.converged = true;
      return result;
    }
    if (!line_search) {
      dv += *delta;
      rhs = problem.residual(dv);
    } else if (minimize) {
      dv += potential_line_search(problem, dv, rhs, *delta);
      rhs = problem.residual(dv);
    } else {
      dv += residual_line_search(problem, dv, rhs, *delta);  // updates rhs
    }
  }
  return result;
}

void ImplicitEuler::advance(State& state) {
  const double h = model().integrator.dt;
  const BackwardEulerStep problem{forces(), state, h};
  Vector dv;
  const NewtonResult plain = solve(problem, /*line_search=*/false, dv);
  NewtonResult result = plain;
  if (!plain.converged) {
    result = solve(problem, /*line_search=*/true, dv);
    if (!result.converged) {
      throw StepError(state.step + 1, "implicit Euler: Newton's method did not converge in " +
                                          std::to_string(settings_.max_iterations) +
                                          " iterations (last correction norm " +
                                          to_text(plain.last_correction_norm) + ", tolerance " +
                                          to_text(settings_.tolerance) +
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

SolverReport ImplicitEuler::solver_report() const {
  SolverReport report;
  report.iterations_of = "newton";
  report.last_step_iterations = last_iterations_;
  report.line_search_steps = line_search_steps_;
  if (solver_ && !course_) report.linear_solves = solver_->statistics();  // else the course's LU
  return report;
}

std::vector<std::string> ImplicitEuler::notes() const {
  if (line_search_steps_ == 0) return {};
  return {"implicit Euler: plain Newton did not converge on " + std::to_string(line_search_steps_) +
          " step(s); they were solved with a line search and may differ from the course's "
          "reference, which has no line search"};
}

namespace {
constexpr std::array<std::string_view, 1> kImplicitEulerAliases = {"implicit"};
constexpr NewtonSettings kImplicitEulerDefaults;
constexpr std::array kImplicitEulerOptionSpecs = {
    OptionSpec::number("newton-tolerance", kImplicitEulerDefaults.tolerance, 0.0, /*excluded=*/true,
                       "stop Newton when the L2 norm of a correction is below this (m/s); "
                       "1e-9 is the course's"),
    OptionSpec::integer("newton-max-iterations", kImplicitEulerDefaults.max_iterations, 1, 1000000,
                        "give up on a step after this many Newton iterations"),
    kSolverOption,
};
}  // namespace

constinit const IntegratorMethod kImplicitEulerMethod{
    .name = "implicit-euler",
    .aliases = kImplicitEulerAliases,
    .summary = "backward Euler solved by Newton's method to 1e-9",
    .options = kImplicitEulerOptionSpecs,
    .properties = {.order = 1,
                   .course_reference = true,
                   .implicit = true,
                   .energy = EnergyTrend::kDecays},
    .create = [](const OptionValues& options, int) -> std::unique_ptr<Integrator> {
      return std::make_unique<ImplicitEuler>(
          NewtonSettings{options.number("newton-tolerance"),
                         options.integer("newton-max-iterations"), solver_choice(options)});
    },
};

}  // namespace fosssim
