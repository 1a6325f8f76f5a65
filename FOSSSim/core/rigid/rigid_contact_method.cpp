#include "core/rigid/rigid_contact_method.h"

#include <utility>

#include "core/rigid/rigid_contact_stage.h"

namespace fosssim {

namespace {

constexpr RigidContactMethod kMethods[] = {
    {"lcp", "inelastic contact: the LCP w = Aλ + b ≥ 0, λ ≥ 0, λᵀw = 0 (ODE's Dantzig solver)",
     true, ContactSolver::kLcp, false, &create_rigid_contact_stage},
    {"velocity-projection",
     "inelastic contact: the closest velocities in the kinetic metric that no contact approaches",
     true, ContactSolver::kVelocityProjection, false, &create_rigid_contact_stage},
    {"gr-lcp", "elastic contact: generalized reflections, each solved as an LCP", true,
     ContactSolver::kLcp, true, &create_rigid_contact_stage},
    {"gr-velocity-projection",
     "elastic contact: generalized reflections, each solved as a velocity projection", true,
     ContactSolver::kVelocityProjection, true, &create_rigid_contact_stage},
};

}  // namespace

std::span<const RigidContactMethod> rigid_contact_methods() { return kMethods; }

const RigidContactMethod* find_rigid_contact_method(std::string_view name) {
  for (const RigidContactMethod& method : kMethods) {
    if (method.name == name) return &method;
  }
  return nullptr;
}

std::unique_ptr<StepStage> make_rigid_contact_stage(const SceneModel& model,
                                                    ContactWarningSink warn) {
  if (!model.rigid_bodies || model.rigid_bodies->contact.method == nullptr) return nullptr;
  const RigidContactMethod& method = *model.rigid_bodies->contact.method;
  return method.create(model, method, model.rigid_bodies->contact, std::move(warn));
}

}  // namespace fosssim
