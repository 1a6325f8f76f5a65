#include "core/integrators/explicit_euler.h"

#include "core/force_evaluation.h"

namespace fosssim {

void ExplicitEuler::advance(const SceneModel& model, State& state) {
  const double h = model.integrator.dt;
  Vector force = compute_force(model, state.q, state.v);
  zero_fixed(model, force);
  state.q += h * state.v;
  state.v += h * force.cwiseQuotient(model.mass);
}

}  // namespace fosssim
