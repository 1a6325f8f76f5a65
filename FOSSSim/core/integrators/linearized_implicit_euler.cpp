#include "core/integrators/linearized_implicit_euler.h"

#include <array>
#include <string_view>

#include "core/force_evaluation.h"
#include "core/integrators/solver_option.h"
#include "core/step_error.h"

namespace fosssim {

void LinearizedImplicitEuler::prepare() {
  matrix_.emplace(forces(), FixedParticleRule::kIdentityRows);
  solver_.emplace(forces().has_symmetric_jacobians(), choice_, model().dim);
  course_ = uses_course_lu(choice_, model().dim, matrix_->size());
}

void LinearizedImplicitEuler::advance(State& state) {
  const double h = model().integrator.dt;
  const Vector predicted_q = state.q + h * state.v;
  const Vector rhs = matrix_->restrict(h * compute_force(forces(), predicted_q, state.v));
  std::optional<Vector> dv;
  if (course_) {
    if (course_lu_.factor(matrix_->assemble_course(predicted_q, state.v, h))) {
      dv = course_lu_.solve(rhs);
    }
  } else {
    dv = solver_->solve(matrix_->assemble(predicted_q, state.v, h), rhs);
  }
  if (!dv) {
    throw StepError(state.step + 1, "linearized implicit Euler: the step matrix is singular");
  }
  matrix_->add_solution(*dv, state.v);
  state.q += h * state.v;
}

namespace {
constexpr std::array<std::string_view, 1> kLinearizedImplicitEulerAliases = {"linearized-implicit"};
constexpr std::array kLinearizedImplicitEulerOptionSpecs = {kSolverOption};
}  // namespace

constinit const IntegratorMethod kLinearizedImplicitEulerMethod{
    .name = "linearized-implicit-euler",
    .aliases = kLinearizedImplicitEulerAliases,
    .summary = "one Newton step of implicit Euler from the predicted position (Baraff-Witkin)",
    .options = kLinearizedImplicitEulerOptionSpecs,
    .properties = {.order = 1,
                   .course_reference = true,
                   .implicit = true,
                   .energy = EnergyTrend::kDecays},
    .create = [](const OptionValues& options, int) -> std::unique_ptr<Integrator> {
      return std::make_unique<LinearizedImplicitEuler>(solver_choice(options));
    },
};

}  // namespace fosssim
