#pragma once
// The interface of every time-stepping method.

#include <memory>
#include <string>
#include <vector>

#include "core/scene_model.h"
#include "core/state.h"

namespace fosssim {

/// Advances a state by one time step of its scene model. Integrators may keep caches (a
/// factorization's symbolic analysis, say) between steps of the same model.
class Integrator {
 public:
  virtual ~Integrator() = default;

  /// Takes one step of h = model.integrator.dt: updates q and v, then step and time.
  /// Throws StepError when the step cannot be taken (a singular system, no convergence).
  void step(const SceneModel& model, State& state) {
    advance(model, state);
    ++state.step;
    state.time = static_cast<double>(state.step) * model.integrator.dt;
  }

  /// Things the user should know about the run so far (for example, fallbacks taken), one
  /// sentence each; empty when there is nothing to say.
  virtual std::vector<std::string> notes() const { return {}; }

 protected:
  /// Updates state.q and state.v from step state.step to state.step + 1.
  virtual void advance(const SceneModel& model, State& state) = 0;
};

/// The integrator named by model.integrator.kind.
std::unique_ptr<Integrator> make_integrator(const SceneModel& model);

}  // namespace fosssim
