#include "core/step/step_pipeline.h"

#include <algorithm>
#include <sstream>

#include "core/collisions/contact_registry.h"
#include "core/solvers/solver_failure.h"
#include "core/step_error.h"

namespace fosssim {

StepPipeline::StepPipeline(const SceneModel& model, StepAdditions additions)
    : model_(&model),
      integrator_(make_integrator(model, std::move(additions.interaction_forces))),
      cancellation_(additions.cancellation) {
  integrator_->set_cancellation(cancellation_);
  if (auto collisions = make_contact_stage(model)) {
    add_stage(StagePhase::kResponse, std::move(collisions));
  }
  for (auto& [phase, stage] : additions.stages) add_stage(phase, std::move(stage));
}

void StepPipeline::add_stage(StagePhase phase, std::unique_ptr<StepStage> stage) {
  const auto after =
      std::upper_bound(stages_.begin(), stages_.end(), phase,
                       [](StagePhase p, const auto& entry) { return p < entry.first; });
  stages_.insert(after, {phase, std::move(stage)});
}

void StepPipeline::step(State& state, StepRecord* record) {
  StepRecord& out = record != nullptr ? *record : own_record_;
  out.clear();
  const std::int64_t step = state.step + 1;
  try {
    if (stages_.empty()) {
      integrator_->step(state);
    } else {
      const State start = state;
      integrator_->step(state);
      cancellation_.check();
      const StepContext context{*model_, start, model_->integrator.dt, out, cancellation_};
      for (auto& [phase, stage] : stages_) stage->apply(context, state);
    }
  } catch (const SolverFailure& failure) {
    // A solver library gave up on this step's matrix: a failed step, named as such.
    throw StepError(step, failure.what());
  }
  if (check_health_) check_state_is_finite(*model_, state);
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
