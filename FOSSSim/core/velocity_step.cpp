#include "core/velocity_step.h"

#include "core/rigid/rigid_bodies.h"

namespace fosssim {

void add_velocity_step(const SceneModel& model, double h, const Vector& force, Vector& v) {
  if (!model.rigid_bodies) {
    v += h * force.cwiseQuotient(model.mass);
    return;
  }
  for (int b = 0; b < model.num_particles(); ++b) {
    const int k = kRigidBodyCoordinates * b;
    const double inverse_mass = 1.0 / model.mass[k];
    v[k] += (force[k] * h) * inverse_mass;
    v[k + 1] += (force[k + 1] * h) * inverse_mass;
    v[k + 2] += (h * force[k + 2]) / model.mass[k + 2];
  }
}

}  // namespace fosssim
