#include "core/integrators/linearly_implicit_euler.h"

#include <array>
#include <string_view>

#include "core/force_evaluation.h"
#include "core/integrators/solver_option.h"
#include "core/step_error.h"

namespace fosssim {

void LinearlyImplicitEuler::prepare() {
  matrix_.emplace(forces(), FixedParticleRule::kElimination, project_hessian_);
  solver_.emplace(forces().has_symmetric_jacobians(), choice_, model().dim);
}

void LinearlyImplicitEuler::advance(State& state) {
  const double h = model().integrator.dt;
  Vector rhs = h * compute_force(forces(), state.q, state.v);
  const SparseMatrix& A = matrix_->assemble(state.q, state.v, h, &state.v, &rhs);
  const auto dv = solver_->solve(A, matrix_->restrict(rhs));
  if (!dv) throw StepError(state.step + 1, "linearly implicit Euler: the step matrix is singular");
  matrix_->add_solution(*dv, state.v);
  state.q += h * state.v;
}

namespace {
constexpr std::array<std::string_view, 2> kHessians = {"exact", "projected"};
constexpr std::array kLinearlyImplicitEulerOptionSpecs = {
    OptionSpec::choice("hessian", kHessians,
                       "\"projected\" makes every element's Hessian semi-definite (compressed "
                       "springs lose their negative transverse stiffness, triangles and hinges "
                       "their negative eigenvalues), so the step matrix stays positive definite"),
    kSolverOption,
};
}  // namespace

constinit const IntegratorMethod kLinearlyImplicitEulerMethod{
    .name = "linearly-implicit-euler",
    .aliases = {},
    .summary = "one linear solve at the current state, fixed particles eliminated (CSC417 a2)",
    .options = kLinearlyImplicitEulerOptionSpecs,
    .properties = {.order = 1, .implicit = true, .energy = EnergyTrend::kDecays},
    .create = [](const OptionValues& options, int) -> std::unique_ptr<Integrator> {
      return std::make_unique<LinearlyImplicitEuler>(options.choice("hessian") == "projected",
                                                     solver_choice(options));
    },
};

}  // namespace fosssim
