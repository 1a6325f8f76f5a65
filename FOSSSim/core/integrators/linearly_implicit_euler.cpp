#include "core/integrators/linearly_implicit_euler.h"

#include "core/force_evaluation.h"
#include "core/step_error.h"

namespace fosssim {

LinearlyImplicitEuler::LinearlyImplicitEuler(const SceneModel& model)
    : solver_(model.has_symmetric_jacobians()) {
  scratch_.set_project_definite(model.integrator.linearly_implicit.project_hessian);
  free_dof_.assign(model.num_dofs(), -1);
  for (int dof = 0; dof < model.num_dofs(); ++dof) {
    if (!model.is_fixed_dof(dof)) free_dof_[dof] = num_free_++;
  }
}

void LinearlyImplicitEuler::advance(const SceneModel& model, State& state) {
  const double h = model.integrator.dt;
  const ForceInput in{state.q, state.v, model.mass};
  Vector rhs = h * compute_force(model, state.q, state.v);
  scratch_.clear();
  scratch_.set_scale(h * h);
  for (const auto& force : model.forces) force->add_hessian_x(in, scratch_);
  for (const Triplet& t : scratch_.triplets()) rhs[t.row()] -= t.value() * state.v[t.col()];
  scratch_.set_scale(h);
  for (const auto& force : model.forces) force->add_hessian_v(in, scratch_);
  scratch_.set_scale(1.0);

  // Project onto the free DOFs: keep the entries whose row and column are both free.
  auto& triplets = scratch_.triplets();
  std::size_t kept = 0;
  for (const Triplet& t : triplets) {
    const int r = free_dof_[t.row()];
    const int c = free_dof_[t.col()];
    if (r >= 0 && c >= 0) triplets[kept++] = Triplet(r, c, t.value());
  }
  triplets.resize(kept);
  Vector reduced_rhs(num_free_);
  for (int dof = 0; dof < model.num_dofs(); ++dof) {
    const int f = free_dof_[dof];
    if (f < 0) continue;
    scratch_.add_diagonal(f, model.mass[dof]);
    reduced_rhs[f] = rhs[dof];
  }
  const SparseMatrix A = scratch_.build(num_free_);
  const auto dv = solver_.solve(A, reduced_rhs);
  if (!dv) throw StepError(state.step + 1, "linearly implicit Euler: the step matrix is singular");
  for (int dof = 0; dof < model.num_dofs(); ++dof) {
    if (free_dof_[dof] >= 0) state.v[dof] += (*dv)[free_dof_[dof]];
  }
  state.q += h * state.v;
}

}  // namespace fosssim
