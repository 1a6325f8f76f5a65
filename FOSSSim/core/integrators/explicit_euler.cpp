#include "core/integrators/explicit_euler.h"

#include "core/force_evaluation.h"
#include "core/velocity_step.h"

namespace fosssim {

void ExplicitEuler::advance(State& state) {
  const double h = model().integrator.dt;
  Vector force = compute_force(forces(), state.q, state.v);
  zero_fixed(model(), force);
  state.q += h * state.v;
  add_velocity_step(model(), h, force, state.v);
}

constinit const IntegratorMethod kExplicitEulerMethod{
    .name = "explicit-euler",
    .summary = "forward Euler, the course's first method",
    .properties = {.order = 1, .course_reference = true, .energy = EnergyTrend::kGrows},
    .create = [](const OptionValues&, int) -> std::unique_ptr<Integrator> {
      return std::make_unique<ExplicitEuler>();
    },
};

}  // namespace fosssim
