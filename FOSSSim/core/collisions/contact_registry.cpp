#include "core/collisions/contact_registry.h"

#include <array>
#include <stdexcept>

#include "core/collisions/continuous_time_collisions.h"
#include "core/collisions/hybrid_collisions.h"
#include "core/collisions/penalty_force.h"
#include "core/collisions/simple_collisions.h"
#include "core/misspelling.h"
#include "core/scene_model.h"
#include "core/step/step_stage.h"

namespace fosssim {

namespace {

/// The course reads COR for every type, so a scene may give it with "none".
constexpr std::array kNoneOptions = {
    particle_contact_options::restitution(
        "accepted and unused (the course reads it for every type)"),
};

/// No contact: nothing collides. A method without code of its own, so its entry is here.
constexpr ContactMethod kNoContactMethod{
    .name = "none",
    .summary = "nothing collides (the same as no <collision> element)",
    .options = kNoneOptions,
    .scope = kParticlesIn2DAnd3D,
};

/// Theme 2's five methods, in the order of the course's handout; the merger of other body
/// kinds adds theirs after them.
constexpr std::array kMethods = {
    &kNoContactMethod,      &kSimpleContactMethod,
    &kPenaltyContactMethod, &kContinuousTimeContactMethod,
    &kHybridContactMethod,
};

std::string dimension_text(const ContactScope& scope) {
  if (scope.runs_2d && !scope.runs_3d) return "2D only";
  if (scope.runs_3d && !scope.runs_2d) return "3D only";
  return "for no dimension";
}

}  // namespace

BodyKind body_kind(const SceneModel& model) {
  return model.rigid_bodies ? BodyKind::kPlanarRigidBodies : BodyKind::kParticles;
}

std::span<const ContactMethod* const> contact_methods() { return kMethods; }

const ContactMethod* find_contact_method(std::string_view name) {
  for (const ContactMethod* method : kMethods) {
    if (method->name == name) return method;
  }
  return nullptr;
}

const ContactMethod& contact_method(std::string_view name) {
  if (const ContactMethod* method = find_contact_method(name)) return *method;
  throw std::logic_error("no contact method is named \"" + std::string(name) + "\"");
}

const ContactMethod& no_contact_method() { return kNoContactMethod; }

std::string describe_contact_method_names() {
  std::string out;
  for (const ContactMethod* method : kMethods) {
    if (!out.empty()) out += ", ";
    out += method->name;
  }
  return out;
}

std::string_view suggest_contact_method(std::string_view unknown) {
  for (const ContactMethod* method : kMethods) {
    if (looks_like_misspelling(unknown, method->name)) return method->name;
  }
  return {};
}

std::string contact_method_refusal(const ContactMethod& method, const SceneModel& model) {
  const ContactScope& scope = method.scope;
  std::string problem;
  if (!scope.handles(body_kind(model))) {
    problem = "\"" + std::string(method.name) + "\" does not handle " +
              (body_kind(model) == BodyKind::kParticles ? "particles" : "rigid bodies");
  } else if (!scope.handles_dim(model.dim)) {
    problem = "\"" + std::string(method.name) + "\" is " + dimension_text(scope);
  } else {
    return "";
  }
  if (!scope.restriction.empty()) problem += " (" + std::string(scope.restriction) + ")";
  return problem;
}

std::unique_ptr<StepStage> make_contact_stage(const SceneModel& model) {
  const ContactMethod& method = *model.collisions.method;
  if (method.make_stage == nullptr) return nullptr;
  return method.make_stage(model);
}

}  // namespace fosssim
