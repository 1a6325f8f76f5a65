#pragma once
// Runs a scene model forward, one checked step at a time.

#include "core/scene_model.h"
#include "core/state.h"
#include "core/step/step_pipeline.h"

namespace fosssim {

/// A scene model, its step pipeline and the current state.
class Simulation {
 public:
  /// `model` must outlive the simulation, and so must the interaction forces of `additions`.
  Simulation(const SceneModel& model, State initial, StepAdditions additions = {});

  /// Takes one step through the pipeline (core/step/step_pipeline.h). Throws StepError if it
  /// fails or leaves a non-finite state; then the state is the one the step produced, for
  /// inspection.
  void step() { pipeline_.step(state_); }

  /// True once model.num_steps() steps have been taken.
  bool finished() const { return state_.step >= pipeline_.model().num_steps(); }

  const SceneModel& model() const { return pipeline_.model(); }
  const Integrator& integrator() const { return pipeline_.integrator(); }
  const State& state() const { return state_; }
  /// What the last step reported besides its state: collisions, polynomials, sync point.
  const StepRecord& last_record() const { return pipeline_.last_record(); }

 private:
  StepPipeline pipeline_;
  State state_;
};

}  // namespace fosssim
