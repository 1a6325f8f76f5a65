#include "viewer/stepper.h"

#include <cmath>
#include <cstdio>

#include "core/step_error.h"
#include "scripting/step_hooks.h"

namespace fosssim {

namespace {
StepAdditions window_additions(const Scene& scene, std::vector<const Force*> interaction_forces,
                               Cancellation cancellation) {
  StepAdditions additions = scripted_additions(scene);
  additions.interaction_forces = std::move(interaction_forces);
  additions.cancellation = cancellation;
  return additions;
}
}  // namespace

SimulationStepper::SimulationStepper(const Scene& scene,
                                     std::vector<const Force*> interaction_forces,
                                     Cancellation cancellation)
    : simulation_(scene.model, scene.initial,
                  window_additions(scene, std::move(interaction_forces), cancellation)) {}

void GradingStepper::step() {
  if (grader_.grade_next_step()) return;
  if (const auto& failure = grader_.report().reference_failure) {
    throw StepError(grader_.file_state().step + 1, *failure);
  }
}

std::vector<ParticleMark> grading_marks(const std::vector<double>& position_residuals,
                                        const std::vector<double>& velocity_residuals,
                                        const GradingCriteria& criteria) {
  const double position_limit = criteria.maximum_limit;
  const double velocity_limit = criteria.maximum_velocity_limit;
  std::vector<ParticleMark> marks;
  for (std::size_t p = 0; p < position_residuals.size(); ++p) {
    const double x = position_residuals[p];
    const double v = velocity_residuals[p];
    // Comparisons written so that NaN fails them.
    if (!(x <= kDisagreeFactor * position_limit && v <= kDisagreeFactor * velocity_limit)) {
      marks.push_back({static_cast<int>(p), kDisagreeColor});
    } else if (!(below_limit(x, position_limit) && below_limit(v, velocity_limit))) {
      marks.push_back({static_cast<int>(p), kFailColor});
    }
  }
  return marks;
}

Overlay GradingStepper::overlay() const {
  Overlay overlay;
  const GradeReport& report = grader_.report();
  overlay.marks = grading_marks(grader_.position_residuals(), grader_.velocity_residuals(),
                                report.criteria);
  char line[160];
  std::snprintf(line, sizeof line, "grading step %lld/%lld: %zu particle(s) disagree",
                static_cast<long long>(grader_.file_state().step),
                static_cast<long long>(report.steps), overlay.marks.size());
  overlay.status.push_back(line);
  if (report.last_step) {
    const StepResidual& last = *report.last_step;
    std::snprintf(line, sizeof line, "step residual: position %.2e, velocity %.2e",
                  last.max_position, last.max_velocity);
    overlay.status.push_back(line);
  }
  if (grader_.finished())
    overlay.status.push_back(report.passed() ? "Overall: Passed" : "Overall: Failed");
  return overlay;
}

}  // namespace fosssim
