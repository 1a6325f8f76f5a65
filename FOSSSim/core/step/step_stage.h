#pragma once
// A stage of the step pipeline: what runs on the state after the integrator.

#include "core/scene_model.h"
#include "core/state.h"
#include "core/step/cancellation.h"
#include "core/step/step_record.h"

namespace fosssim {

/// When a stage runs within a step, after the integrator. Stages run in this order, and in the
/// order they were added within a phase.
enum class StagePhase {
  kResponse,    ///< responses to events of the step: collision handling
  kConstraint,  ///< projections onto constraints
  kScript,      ///< the scene's scripted behaviour (its scenetag)
};

/// What a stage may consult besides the state it adjusts.
struct StepContext {
  const SceneModel& model;
  /// The state the step started from: qⁿ, vⁿ, and the step number and time of step n.
  const State& start;
  double h;  ///< the time step, s
  /// What the step reports besides its end state (collisions, polynomials, sync point);
  /// cleared before the integrator runs, appended to by the stages.
  StepRecord& record;
  /// Asked once per iteration by stages that iterate (hybrid passes, impact zones).
  Cancellation cancellation;
};

/// One stage of a step (core/step/step_pipeline.h). A stage must be a function of what it is
/// handed, keeping no memory between steps (or only memory it can rebuild from them, such as
/// a cache), and draw any randomness from the step number: a run, a rerun and the grader's
/// replay from recorded frames then apply it identically.
class StepStage {
 public:
  virtual ~StepStage() = default;
  /// Adjusts `state`, the end of the step so far; state.step and state.time already name the
  /// new step.
  virtual void apply(const StepContext& context, State& state) = 0;
};

}  // namespace fosssim
