#include "core/force_evaluation.h"

namespace fosssim {

Vector gradient_of(const Force& force, const Vector& q, const Vector& v, const Vector& mass) {
  Vector g = Vector::Zero(q.size());
  force.add_gradient({q, v, mass}, g);
  return g;
}

double energy_of(const Force& force, const Vector& q, const Vector& v, const Vector& mass) {
  double energy = 0.0;
  force.add_energy({q, v, mass}, energy);
  return energy;
}

Vector compute_gradient(const ForceSet& forces, const Vector& q, const Vector& v) {
  Vector gradient = Vector::Zero(q.size());
  const ForceInput in{q, v, forces.mass()};
  for (const Force* force : forces) force->add_gradient(in, gradient);
  return gradient;
}

Vector compute_force(const ForceSet& forces, const Vector& q, const Vector& v) {
  return -compute_gradient(forces, q, v);
}

double compute_potential_energy(const ForceSet& forces, const Vector& q, const Vector& v) {
  double energy = 0.0;
  const ForceInput in{q, v, forces.mass()};
  for (const Force* force : forces) force->add_energy(in, energy);
  return energy;
}

double compute_kinetic_energy(const SceneModel& model, const Vector& v) {
  return 0.5 * v.dot(model.mass.cwiseProduct(v));
}

SparseMatrix compute_hessian_x(const ForceSet& forces, const Vector& q, const Vector& v) {
  HessianBuilder builder;
  const ForceInput in{q, v, forces.mass()};
  for (const Force* force : forces) force->add_hessian_x(in, builder);
  return builder.build(static_cast<int>(q.size()));
}

SparseMatrix compute_hessian_v(const ForceSet& forces, const Vector& q, const Vector& v) {
  HessianBuilder builder;
  const ForceInput in{q, v, forces.mass()};
  for (const Force* force : forces) force->add_hessian_v(in, builder);
  return builder.build(static_cast<int>(q.size()));
}

void zero_fixed(const SceneModel& model, Vector& x) {
  const int dim = model.dim;
  for (int p = 0; p < model.num_particles(); ++p) {
    if (model.fixed[p]) x.segment(dim * p, dim).setZero();
  }
}

}  // namespace fosssim
