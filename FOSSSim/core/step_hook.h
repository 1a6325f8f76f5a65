#pragma once
// Scripted behaviour a scene attaches to its run, applied after every integrator step.

#include "core/scene_model.h"
#include "core/state.h"

namespace fosssim {

/// Something a scene does besides its physics (SPEC section 6: the ParticleFountain's teleport).
/// A hook is a pure function of the state it is handed: it keeps no memory between steps and
/// draws any randomness from the step number, so that a run, a rerun and the grader's replay
/// from recorded frames all apply it identically. Hooks are made from a scene's tag by
/// make_step_hook (scripting/step_hooks.h); the core only calls them.
class StepHook {
 public:
  virtual ~StepHook() = default;

  /// Adjusts the state the integrator has just produced; state.step and state.time already
  /// name the new step.
  virtual void after_step(const SceneModel& model, State& state) const = 0;
};

}  // namespace fosssim
