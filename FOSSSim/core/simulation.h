#pragma once
// Runs a scene model forward, one checked step at a time.

#include <memory>

#include "core/integrators/integrator.h"
#include "core/scene_model.h"
#include "core/state.h"
#include "core/step_hook.h"

namespace fosssim {

/// A scene model, its integrator, an optional scripted hook and the current state. Every step
/// is the integrator's step, then the hook, then a health check, so a non-finite position or
/// velocity stops the run at the step that produced it.
class Simulation {
 public:
  /// model must outlive the simulation; hook (may be null) runs after every integrator step.
  Simulation(const SceneModel& model, State initial, std::unique_ptr<const StepHook> hook = {});

  /// Takes one step. Throws StepError if it fails or leaves a non-finite state; then the state
  /// is the one the step produced, for inspection.
  void step();

  /// True once model.num_steps() steps have been taken.
  bool finished() const { return state_.step >= model_.num_steps(); }

  const SceneModel& model() const { return model_; }
  const Integrator& integrator() const { return *integrator_; }
  const State& state() const { return state_; }
  /// The state, for grading (which restarts every step from a reference frame) and scripting.
  State& mutable_state() { return state_; }

 private:
  const SceneModel& model_;
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<const StepHook> hook_;
  State state_;
};

/// Throws StepError naming the first particle whose position or velocity is NaN or infinite.
void check_state_is_finite(const SceneModel& model, const State& state);

}  // namespace fosssim
