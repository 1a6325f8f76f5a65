#include "core/step/simulation.h"

namespace fosssim {

Simulation::Simulation(const SceneModel& model, State initial, StepAdditions additions)
    : pipeline_(model, std::move(additions)), state_(std::move(initial)) {}

}  // namespace fosssim
