#pragma once

#include "core/scene_model.h"
#include "core/state.h"

namespace fosssim {

/// Kinetic, potential and total energy of a state (diagnostic only: damping, drag and vortices
/// are not part of the potential).
struct EnergyReport {
  double kinetic = 0.0;
  double potential = 0.0;
  double total() const { return kinetic + potential; }
};

EnergyReport compute_energies(const SceneModel& model, const State& state);

}  // namespace fosssim
