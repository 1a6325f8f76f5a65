#include "core/rigid/rigid_contact_stage.h"

#include <iostream>
#include <utility>

namespace fosssim {

RigidContactStage::RigidContactStage(const SceneModel& model, const RigidContactMethod& method,
                                     const RigidContactSettings& settings, ContactWarningSink warn)
    : model_(&model), method_(&method), settings_(settings), warn_(std::move(warn)) {
  if (!warn_) {
    warn_ = [](const std::string& line) { std::cerr << line << "\n"; };
  }
}

void RigidContactStage::apply(const StepContext& context, State& state) {
  const RigidBodies& bodies = *model_->rigid_bodies;
  const std::vector<RigidContact> contacts = detect_rigid_contacts(bodies, state.q);
  report_ = ContactReport{};
  report_.contacts = static_cast<int>(contacts.size());
  if (contacts.empty()) return;
  if (method_->generalized_reflections) {
    apply_generalized_reflections(method_->solver, bodies, state.q, contacts,
                                  settings_.max_reflections, state.v, report_, context.cancellation,
                                  settings_.max_group_contacts);
  } else {
    apply_inelastic_response(method_->solver, bodies, state.q, contacts, state.v, report_,
                             settings_.max_group_contacts);
  }
  context.cancellation.check();
  if (report_.fallbacks > 0 && !warned_) {
    warned_ = true;
    warn_("FOSSSim: warning: step " + std::to_string(state.step) + ": rigid-body contact (" +
          std::string(method_->name) + "): " + report_.fallback_reason +
          "; FOSSSim solved it exactly by velocity projection (the velocities every valid "
          "impulse gives); the course's LCP solver sometimes stops early or loops on such "
          "problems, so its program may differ on such steps (warned once per run)");
  }
}

std::unique_ptr<StepStage> create_rigid_contact_stage(const SceneModel& model,
                                                      const RigidContactMethod& method,
                                                      const RigidContactSettings& settings,
                                                      ContactWarningSink warn) {
  return std::make_unique<RigidContactStage>(model, method, settings, std::move(warn));
}

}  // namespace fosssim
