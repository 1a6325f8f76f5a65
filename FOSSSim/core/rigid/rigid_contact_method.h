#pragma once
// The responses to contact between rigid bodies that <rigidbodycollisionhandling response="...">
// names, in one place: names, summaries and the stage each makes (docs/rigid-bodies.md).

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "core/rigid/rigid_contact_response.h"
#include "core/rigid/rigid_contact_settings.h"
#include "core/step/step_stage.h"

namespace fosssim {

/// Receives run-time warnings of a contact stage (one line, no newline).
using ContactWarningSink = std::function<void(const std::string&)>;

/// One response method.
struct RigidContactMethod {
  std::string_view name;     ///< the response="..." string (case-sensitive, as the course)
  std::string_view summary;  ///< one line for messages and docs
  /// The course's own method: trajectories match its program to round-off on non-degenerate
  /// contact (docs/rigid-bodies.md, "What is course-compatible").
  bool course_reference = true;
  ContactSolver solver = ContactSolver::kLcp;
  bool generalized_reflections = false;
  /// Makes the response stage for `model` (which must outlive it); warnings go to `warn`.
  std::unique_ptr<StepStage> (*create)(const SceneModel& model, const RigidContactMethod& method,
                                       const RigidContactSettings& settings,
                                       ContactWarningSink warn) = nullptr;
};

/// The methods, in the order the docs list them: lcp, velocity-projection, gr-lcp,
/// gr-velocity-projection.
std::span<const RigidContactMethod> rigid_contact_methods();
/// The method named `name`, or null.
const RigidContactMethod* find_rigid_contact_method(std::string_view name);

/// The contact stage of a rigid-body model with <rigidbodycollisionhandling>, or null. Warnings
/// go to standard error unless `warn` is given.
std::unique_ptr<StepStage> make_rigid_contact_stage(const SceneModel& model,
                                                    ContactWarningSink warn = {});

}  // namespace fosssim
