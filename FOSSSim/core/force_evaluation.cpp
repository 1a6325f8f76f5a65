#include "core/force_evaluation.h"

#include <algorithm>

namespace fosssim {

Vector compute_gradient(const SceneModel& model, const Vector& q, const Vector& v) {
  Vector gradient = Vector::Zero(q.size());
  const ForceInput in{q, v, model.mass};
  for (const auto& force : model.forces) force->add_gradient(in, gradient);
  return gradient;
}

Vector compute_force(const SceneModel& model, const Vector& q, const Vector& v) {
  return -compute_gradient(model, q, v);
}

double compute_potential_energy(const SceneModel& model, const Vector& q, const Vector& v) {
  double energy = 0.0;
  const ForceInput in{q, v, model.mass};
  for (const auto& force : model.forces) force->add_energy(in, energy);
  return energy;
}

double compute_kinetic_energy(const SceneModel& model, const Vector& v) {
  return 0.5 * v.dot(model.mass.cwiseProduct(v));
}

SparseMatrix compute_hessian_x(const SceneModel& model, const Vector& q, const Vector& v) {
  HessianBuilder builder;
  const ForceInput in{q, v, model.mass};
  for (const auto& force : model.forces) force->add_hessian_x(in, builder);
  return builder.build(static_cast<int>(q.size()));
}

SparseMatrix compute_hessian_v(const SceneModel& model, const Vector& q, const Vector& v) {
  HessianBuilder builder;
  const ForceInput in{q, v, model.mass};
  for (const auto& force : model.forces) force->add_hessian_v(in, builder);
  return builder.build(static_cast<int>(q.size()));
}

void zero_fixed(const SceneModel& model, Vector& x) {
  const int dim = model.dim;
  for (int p = 0; p < model.num_particles(); ++p) {
    if (model.fixed[p]) x.segment(dim * p, dim).setZero();
  }
}

SparseMatrix assemble_step_matrix(const SceneModel& model, const Vector& q, const Vector& v,
                                  double h, HessianBuilder& scratch, Vector* hessian_x_times_v) {
  scratch.clear();
  const ForceInput in{q, v, model.mass};
  scratch.set_scale(h * h);
  for (const auto& force : model.forces) force->add_hessian_x(in, scratch);
  if (hessian_x_times_v) {
    hessian_x_times_v->setZero(model.num_dofs());
    for (const Triplet& t : scratch.triplets()) {
      (*hessian_x_times_v)[t.row()] += t.value() * v[t.col()];
    }
  }
  scratch.set_scale(h);
  for (const auto& force : model.forces) force->add_hessian_v(in, scratch);
  scratch.set_scale(1.0);
  const int n = model.num_dofs();
  if (model.has_fixed_particles()) {
    std::erase_if(scratch.triplets(), [&model](const Triplet& t) {
      return model.is_fixed_dof(t.row()) || model.is_fixed_dof(t.col());
    });
  }
  for (int dof = 0; dof < n; ++dof) {
    scratch.add_diagonal(dof, model.is_fixed_dof(dof) ? 1.0 : model.mass[dof]);
  }
  return scratch.build(n);
}

}  // namespace fosssim
