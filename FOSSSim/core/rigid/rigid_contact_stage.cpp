#include "core/rigid/rigid_contact_stage.h"

#include <array>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/rigid/rigid_bodies.h"
#include "core/scene_model.h"

namespace fosssim {

RigidContactStage::RigidContactStage(const SceneModel& model, const ContactMethod& method,
                                     ContactWarningSink warn)
    : model_(&model), method_(&method), warn_(std::move(warn)) {
  if (method.rigid_response == nullptr || !model.rigid_bodies) {
    throw std::logic_error("contact method \"" + std::string(method.name) +
                           "\" has no rigid-body stage for this model");
  }
  response_ = *method.rigid_response;
  settings_ = model.rigid_bodies->contact;
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
  if (response_.generalized_reflections) {
    apply_generalized_reflections(response_.solver, bodies, state.q, contacts,
                                  settings_.max_reflections, state.v, report_, context.cancellation,
                                  settings_.max_group_contacts);
  } else {
    apply_inelastic_response(response_.solver, bodies, state.q, contacts, state.v, report_,
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

namespace {

/// Every entry's ContactMethod::make_stage: the stage of model.collisions' method.
std::unique_ptr<StepStage> make_rigid_stage(const SceneModel& model) {
  return std::make_unique<RigidContactStage>(model, *model.collisions.method);
}

// FOSSSim's limits (the course's program has none), attributes of <rigidbodycollisionhandling>;
// the loader copies them into RigidContactSettings.
constexpr OptionSpec kRigidMaxReflectionsOption = OptionSpec::integer(
    "maxreflections", RigidContactSettings::kDefaultMaxReflections, 1,
    std::numeric_limits<int>::max(),
    "FOSSSim's limit: the most generalized reflections of one step (more is a failed step)");
constexpr OptionSpec kRigidMaxGroupContactsOption = OptionSpec::integer(
    "maxgroupcontacts", RigidContactSettings::kDefaultMaxGroupContacts, 1,
    std::numeric_limits<int>::max(),
    "FOSSSim's limit: the most contacts of one group of touching bodies, solved as one dense "
    "problem (more is a failed step)");
constexpr std::array kRigidInelasticOptions = {kRigidMaxGroupContactsOption};
constexpr std::array kRigidReflectionOptions = {kRigidMaxReflectionsOption, kRigidMaxGroupContactsOption};

constexpr RigidResponse kLcp{ContactSolver::kLcp, false};
constexpr RigidResponse kVelocityProjection{ContactSolver::kVelocityProjection, false};
constexpr RigidResponse kGrLcp{ContactSolver::kLcp, true};
constexpr RigidResponse kGrVelocityProjection{ContactSolver::kVelocityProjection, true};

}  // namespace

// All four are the course's own methods: their trajectories match its program to round-off on
// non-degenerate contact (docs/rigid-bodies.md, "What is course-compatible").

constinit const ContactMethod kLcpContactMethod{
    .name = "lcp",
    .summary = "inelastic contact: the LCP w = Aλ + b ≥ 0, λ ≥ 0, λᵀw = 0 (ODE's Dantzig solver)",
    .options = kRigidInelasticOptions,
    .scope = kPlanarRigidBodies,
    .make_stage = &make_rigid_stage,
    .rigid_response = &kLcp,
};

constinit const ContactMethod kVelocityProjectionContactMethod{
    .name = "velocity-projection",
    .summary = "inelastic contact: the closest velocities in the kinetic metric that no contact "
               "approaches",
    .options = kRigidInelasticOptions,
    .scope = kPlanarRigidBodies,
    .make_stage = &make_rigid_stage,
    .rigid_response = &kVelocityProjection,
};

constinit const ContactMethod kGrLcpContactMethod{
    .name = "gr-lcp",
    .summary = "elastic contact: generalized reflections, each solved as an LCP",
    .options = kRigidReflectionOptions,
    .scope = kPlanarRigidBodies,
    .make_stage = &make_rigid_stage,
    .rigid_response = &kGrLcp,
    .in_course_messages = false,
};

constinit const ContactMethod kGrVelocityProjectionContactMethod{
    .name = "gr-velocity-projection",
    .summary = "elastic contact: generalized reflections, each solved as a velocity projection",
    .options = kRigidReflectionOptions,
    .scope = kPlanarRigidBodies,
    .make_stage = &make_rigid_stage,
    .rigid_response = &kGrVelocityProjection,
    .in_course_messages = false,
};

}  // namespace fosssim
