#include "core/forces/rigid_body_gravity_force.h"

#include "core/rigid/rigid_bodies.h"
#include "core/scene_model.h"

namespace fosssim {

void require_rigid_body_scene(ForceParameters& params, const ForceContext& context) {
  if (!context.model.rigid_bodies) {
    params.fail("acts on rigid bodies only: the scene needs <simtype type=\"rigid-body\"/>");
  }
}

void RigidBodyGravityForce::add_energy(const ForceInput& in, double& energy) const {
  const int bodies = static_cast<int>(in.q.size()) / kRigidBodyCoordinates;
  double sum = 0.0;
  for (int b = 0; b < bodies; ++b) {
    const int k = kRigidBodyCoordinates * b;
    sum += (g_.y() * in.q[k + 1] + g_.x() * in.q[k]) * -in.mass[k];
  }
  energy = sum + energy;
}

void RigidBodyGravityForce::add_gradient(const ForceInput& in, Vector& gradient) const {
  const int bodies = static_cast<int>(in.q.size()) / kRigidBodyCoordinates;
  for (int b = 0; b < bodies; ++b) {
    const int k = kRigidBodyCoordinates * b;
    gradient[k] -= in.mass[k] * g_.x();
    gradient[k + 1] -= in.mass[k] * g_.y();
  }
}

std::unique_ptr<Force> make_rigid_body_gravity_force(ForceParameters& params,
                                                     const ForceContext& context) {
  require_rigid_body_scene(params, context);
  return std::make_unique<RigidBodyGravityForce>(Vec<2>(params.number("fx"), params.number("fy")));
}

}  // namespace fosssim
