#pragma once
// The step stage of rigid-body contact (detection on the integrated state, then the response)
// and the four responses <rigidbodycollisionhandling response="..."> names, as entries of the
// contact registry (core/collisions/contact_registry.h; docs/rigid-bodies.md, "Contact").

#include <functional>
#include <memory>
#include <string>

#include "core/collisions/contact_method.h"
#include "core/rigid/rigid_contact_response.h"
#include "core/step/step_stage.h"

namespace fosssim {

/// What a rigid-body contact method does after detection: the inelastic problem it solves, and
/// whether it repeats it as generalized reflections (elastic) or applies it once (inelastic).
/// ContactMethod::rigid_response of the four entries below.
struct RigidResponse {
  ContactSolver solver = ContactSolver::kLcp;
  bool generalized_reflections = false;
};

/// Receives run-time warnings of a contact stage (one line, no newline).
using ContactWarningSink = std::function<void(const std::string&)>;

/// Runs after the integrator (StagePhase::kResponse): detects the contacts of the new positions
/// (detect_rigid_contacts) and applies `method`'s response (ContactMethod::rigid_response) to
/// the velocities of the free bodies, with the limits of model.rigid_bodies->contact. Positions
/// are left as integrated, as in the course. Warns once per run (through the sink, naming the
/// step) when the LCP needed the fallback of degenerate contact; without a sink, to standard
/// error.
class RigidContactStage final : public StepStage {
 public:
  RigidContactStage(const SceneModel& model, const ContactMethod& method,
                    ContactWarningSink warn = {});
  void apply(const StepContext& context, State& state) override;
  /// What the last step's response did.
  const ContactReport& last_report() const { return report_; }

 private:
  const SceneModel* model_;
  const ContactMethod* method_;
  RigidResponse response_;
  RigidContactSettings settings_;
  ContactWarningSink warn_;
  bool warned_ = false;
  ContactReport report_;
};

/// The course's two inelastic responses and their generalized reflections, in the order the
/// docs list them. Each entry's stage is a RigidContactStage.
extern const ContactMethod kLcpContactMethod;                     ///< "lcp"
extern const ContactMethod kVelocityProjectionContactMethod;      ///< "velocity-projection"
extern const ContactMethod kGrLcpContactMethod;                   ///< "gr-lcp"
extern const ContactMethod kGrVelocityProjectionContactMethod;    ///< "gr-velocity-projection"

}  // namespace fosssim
