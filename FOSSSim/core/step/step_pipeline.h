#pragma once
// One step of a scene: the integrator, then the stages that follow it, then a health check.

#include <memory>
#include <utility>
#include <vector>

#include "core/integrators/integrator.h"
#include "core/scene_model.h"
#include "core/state.h"
#include "core/step/step_record.h"
#include "core/step/step_stage.h"

namespace fosssim {

/// What the caller of a simulation adds to a scene model's own step.
struct StepAdditions {
  /// Forces the caller owns, summed after the model's and seen by the integrator like them
  /// (the window's drag spring, core/forces/drag_spring_force.h). See core/force_set.h.
  std::vector<const Force*> interaction_forces;
  /// Stages the caller adds, with their phase (the scene tag's scripted behaviour,
  /// scripting/step_hooks.h, is a kScript stage).
  std::vector<std::pair<StagePhase, std::unique_ptr<StepStage>>> stages;
  /// Lets the caller end a step in progress (core/step/cancellation.h): the integrator's
  /// iterations and the stages' passes ask it, and step() then throws StepCancelled.
  Cancellation cancellation;
};

/// Everything one step of a scene does, in order:
///   1. the model's integrator takes the step (core/integrators/);
///   2. the stages, by phase: responses (collision handling), constraint projections, then
///      scripts (the scene's scripted behaviour), each with the start state at hand;
///   3. the health check: a non-finite position or velocity stops the run at the step that
///      produced it (StepError naming the particle), unless turned off.
/// A run (Simulation) and the grader, which restarts every step from a recorded frame, step
/// through the same pipeline, so both do exactly the same thing.
class StepPipeline {
 public:
  /// Makes and precomputes the model's integrator (make_integrator) and adds the model's
  /// contact method's response stage, if it has one (make_contact_stage,
  /// core/collisions/contact_registry.h);
  /// `model` must outlive the pipeline, and so must the interaction forces of `additions`.
  explicit StepPipeline(const SceneModel& model, StepAdditions additions = {});

  /// Adds a stage; it runs after those of earlier phases and those added before it.
  void add_stage(StagePhase phase, std::unique_ptr<StepStage> stage);
  /// The grader compares states as they come, non-finite ones included; runs check them.
  void set_health_check(bool on) { check_health_ = on; }

  /// Takes one step of `state`. Throws StepError when a stage or the health check fails.
  /// `record` (cleared first) receives what the stages report about the step; without one the
  /// pipeline uses a record of its own (last_record()).
  void step(State& state, StepRecord* record = nullptr);
  /// The record of the last step taken without a record of the caller's.
  const StepRecord& last_record() const { return own_record_; }

  const SceneModel& model() const { return *model_; }
  const Integrator& integrator() const { return *integrator_; }

 private:
  const SceneModel* model_;
  std::unique_ptr<Integrator> integrator_;
  std::vector<std::pair<StagePhase, std::unique_ptr<StepStage>>> stages_;  // sorted by phase
  bool check_health_ = true;
  Cancellation cancellation_;
  StepRecord own_record_;
};

/// Throws StepError naming the first particle whose position or velocity is NaN or infinite.
void check_state_is_finite(const SceneModel& model, const State& state);

}  // namespace fosssim
