#include "core/analysis/energy.h"

#include "core/force_evaluation.h"

namespace fosssim {

EnergyReport compute_energies(const SceneModel& model, const State& state) {
  return {compute_kinetic_energy(model, state.v),
          compute_potential_energy(ForceSet(model), state.q, state.v)};
}

}  // namespace fosssim
