#pragma once
// The step stage of rigid-body contact: detection on the integrated state, then the response.

#include "core/rigid/rigid_contact_method.h"

namespace fosssim {

/// Runs after the integrator (StagePhase::kResponse): detects the contacts of the new positions
/// (detect_rigid_contacts) and applies the method's response to the velocities of the free
/// bodies. Positions are left as integrated, as in the course. Warns once per run (through the
/// sink, naming the step) when the LCP needed the fallback of degenerate contact.
class RigidContactStage final : public StepStage {
 public:
  RigidContactStage(const SceneModel& model, const RigidContactMethod& method,
                    const RigidContactSettings& settings, ContactWarningSink warn);
  void apply(const StepContext& context, State& state) override;
  /// What the last step's response did.
  const ContactReport& last_report() const { return report_; }

 private:
  const SceneModel* model_;
  const RigidContactMethod* method_;
  RigidContactSettings settings_;
  ContactWarningSink warn_;
  bool warned_ = false;
  ContactReport report_;
};

/// RigidContactMethod::create of every method.
std::unique_ptr<StepStage> create_rigid_contact_stage(const SceneModel& model,
                                                      const RigidContactMethod& method,
                                                      const RigidContactSettings& settings,
                                                      ContactWarningSink warn);

}  // namespace fosssim
