#include "core/collisions/contact_registry.h"

#include <array>
#include <stdexcept>

#include "core/collisions/continuous_time_collisions.h"
#include "core/collisions/hybrid_collisions.h"
#include "core/collisions/penalty_force.h"
#include "core/collisions/simple_collisions.h"
#include "core/misspelling.h"
#include "core/rigid/rigid_contact_stage.h"
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

/// Every method, one line each: Theme 2's five particle methods in the order of the course's
/// handout, then Theme 3's four rigid-body responses in the order of docs/rigid-bodies.md.
constexpr std::array kMethods = {
    &kNoContactMethod,
    &kSimpleContactMethod,
    &kPenaltyContactMethod,
    &kContinuousTimeContactMethod,
    &kHybridContactMethod,
    &kLcpContactMethod,
    &kVelocityProjectionContactMethod,
    &kGrLcpContactMethod,
    &kGrVelocityProjectionContactMethod,
};

std::string dimension_text(const ContactScope& scope) {
  if (scope.runs_2d && !scope.runs_3d) return "2D only";
  if (scope.runs_3d && !scope.runs_2d) return "3D only";
  return "for no dimension";
}

std::string_view kind_name(BodyKind kind) {
  return kind == BodyKind::kParticles ? "particles" : "rigid bodies";
}

/// Where a scene names a method for bodies of `kind`.
std::string_view naming_element(BodyKind kind) {
  return kind == BodyKind::kParticles ? "<collision type=\"...\">"
                                      : "<rigidbodycollisionhandling response=\"...\">";
}

}  // namespace

BodyKind body_kind(const SceneModel& model) {
  return model.rigid_bodies ? BodyKind::kPlanarRigidBodies : BodyKind::kParticles;
}

int body_dimension(const SceneModel& model) { return model.rigid_bodies ? 2 : model.dim; }

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

std::string describe_contact_method_names(BodyKind kind) {
  std::string out;
  for (const ContactMethod* method : kMethods) {
    if (!method->scope.handles(kind)) continue;
    if (!out.empty()) out += ", ";
    out += method->name;
  }
  return out;
}

std::string_view suggest_contact_method(std::string_view unknown, BodyKind kind) {
  for (const ContactMethod* method : kMethods) {
    if (method->scope.handles(kind) && looks_like_misspelling(unknown, method->name)) return method->name;
  }
  return {};
}

std::string contact_method_refusal(const ContactMethod& method, const SceneModel& model) {
  const ContactScope& scope = method.scope;
  const std::string name = "\"" + std::string(method.name) + "\"";
  const BodyKind kind = body_kind(model);
  if (!scope.handles(kind)) {
    // A method handles one kind of body, named by that kind's element.
    const BodyKind other =
        kind == BodyKind::kParticles ? BodyKind::kPlanarRigidBodies : BodyKind::kParticles;
    return name + " does not handle " + std::string(kind_name(kind)) + " (it is a method of " +
           std::string(kind_name(other)) + ", named by " + std::string(naming_element(other)) +
           ")";
  }
  if (scope.handles_dim(body_dimension(model))) return "";
  std::string problem = name + " is " + dimension_text(scope);
  if (!scope.restriction.empty()) problem += " (" + std::string(scope.restriction) + ")";
  return problem;
}

std::unique_ptr<StepStage> make_contact_stage(const SceneModel& model) {
  const ContactMethod& method = *model.collisions.method;
  if (method.make_stage == nullptr) return nullptr;
  return method.make_stage(model);
}

}  // namespace fosssim
