#include "core/simulation.h"

#include <cmath>
#include <sstream>

#include "core/step_error.h"

namespace fosssim {

Simulation::Simulation(const SceneModel& model, State initial, std::unique_ptr<const StepHook> hook)
    : model_(model),
      integrator_(make_integrator(model)),
      hook_(std::move(hook)),
      state_(std::move(initial)) {}

void Simulation::step() {
  integrator_->step(model_, state_);
  if (hook_) hook_->after_step(model_, state_);
  check_state_is_finite(model_, state_);
}

void check_state_is_finite(const SceneModel& model, const State& state) {
  if (state.q.allFinite() && state.v.allFinite()) return;
  const int dim = model.dim;
  for (int p = 0; p < model.num_particles(); ++p) {
    const auto x = state.q.segment(dim * p, dim);
    const auto v = state.v.segment(dim * p, dim);
    if (x.allFinite() && v.allFinite()) continue;
    std::ostringstream message;
    message << "particle " << p << " has a non-finite "
            << (x.allFinite() ? "velocity (" : "position (");
    const auto bad = x.allFinite() ? v : x;
    for (int c = 0; c < dim; ++c) message << (c ? ", " : "") << bad[c];
    message << "); the simulation has blown up (try a smaller time step or another integrator)";
    throw StepError(state.step, message.str());
  }
}

}  // namespace fosssim
