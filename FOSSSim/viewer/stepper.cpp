#include "viewer/stepper.h"

#include <cmath>
#include <cstdio>

#include "core/step_error.h"
#include "scripting/step_hooks.h"

namespace fosssim {

namespace {
StepAdditions window_additions(const Scene& scene, std::vector<const Force*> interaction_forces) {
  StepAdditions additions = scripted_additions(scene);
  additions.interaction_forces = std::move(interaction_forces);
  return additions;
}
}  // namespace

SimulationStepper::SimulationStepper(const Scene& scene,
                                     std::vector<const Force*> interaction_forces)
    : simulation_(scene.model, scene.initial,
                  window_additions(scene, std::move(interaction_forces))) {}

void GradingStepper::step() {
  if (grader_.grade_next_step()) return;
  if (const auto& failure = grader_.report().reference_failure) {
    throw StepError(grader_.file_state().step + 1, *failure);
  }
}

std::vector<ParticleMark> grading_marks(const std::vector<double>& position_residuals,
                                        const std::vector<double>& velocity_residuals,
                                        double maximum_limit) {
  std::vector<ParticleMark> marks;
  for (std::size_t p = 0; p < position_residuals.size(); ++p) {
    const double r = std::fmax(position_residuals[p], velocity_residuals[p]);
    const bool nan = std::isnan(position_residuals[p]) || std::isnan(velocity_residuals[p]);
    if (nan || r > kDisagreeResidual) {
      marks.push_back({static_cast<int>(p), kDisagreeColor});
    } else if (!(r < maximum_limit)) {
      marks.push_back({static_cast<int>(p), kFailColor});
    }
  }
  return marks;
}

Overlay GradingStepper::overlay() const {
  Overlay overlay;
  const GradeReport& report = grader_.report();
  overlay.marks = grading_marks(grader_.position_residuals(), grader_.velocity_residuals(),
                                report.criteria.maximum_limit);
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
