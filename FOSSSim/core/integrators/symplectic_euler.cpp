#include "core/integrators/symplectic_euler.h"

#include "core/force_evaluation.h"

namespace fosssim {

void SymplecticEuler::advance(const SceneModel& model, State& state) {
  const double h = model.integrator.dt;
  Vector force = compute_force(model, state.q, state.v);
  zero_fixed(model, force);
  state.v += h * force.cwiseQuotient(model.mass);
  state.q += h * state.v;
}

}  // namespace fosssim
