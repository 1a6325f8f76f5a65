#include "core/systems/step_matrix.h"

#include <algorithm>

#include "core/force_evaluation.h"

namespace fosssim {

StepMatrix::StepMatrix(const ForceSet& forces, FixedParticleRule rule, bool definite_hessian)
    : forces_(&forces),
      rule_(rule),
      definite_hessian_(definite_hessian),
      free_(forces.model().fixed, forces.model().dim),
      any_fixed_(forces.model().has_fixed_particles()) {}

int StepMatrix::size() const {
  return rule_ == FixedParticleRule::kElimination ? free_.num_dofs() : forces_->model().num_dofs();
}

const SparseMatrix& StepMatrix::assemble(const Vector& q, const Vector& v, double h,
                                         const Vector* u, Vector* rhs) {
  const SceneModel& model = forces_->model();
  const ForceInput in{q, v, model.mass, definite_hessian_};
  scratch_.clear();
  scratch_.set_scale(h * h);
  for (const Force* force : *forces_) force->add_hessian_x(in, scratch_);
  if (rhs != nullptr) {
    for (const Triplet& t : scratch_.triplets()) (*rhs)[t.row()] -= t.value() * (*u)[t.col()];
  }
  scratch_.set_scale(h);
  for (const Force* force : *forces_) force->add_hessian_v(in, scratch_);
  scratch_.set_scale(1.0);
  auto& triplets = scratch_.triplets();
  if (rule_ == FixedParticleRule::kIdentityRows) {
    if (any_fixed_) {
      std::erase_if(triplets, [&model](const Triplet& t) {
        return model.is_fixed_dof(t.row()) || model.is_fixed_dof(t.col());
      });
    }
    for (int dof = 0; dof < model.num_dofs(); ++dof) {
      scratch_.add_diagonal(dof, model.is_fixed_dof(dof) ? 1.0 : model.mass[dof]);
    }
  } else {
    std::size_t kept = 0;
    for (const Triplet& t : triplets) {
      const int r = free_.of_dof(t.row());
      const int c = free_.of_dof(t.col());
      if (r >= 0 && c >= 0) triplets[kept++] = Triplet(r, c, t.value());
    }
    triplets.resize(kept);
    for (int dof = 0; dof < model.num_dofs(); ++dof) {
      const int f = free_.of_dof(dof);
      if (f >= 0) scratch_.add_diagonal(f, model.mass[dof]);
    }
  }
  matrix_ = scratch_.build(size());
  return matrix_;
}

Vector StepMatrix::restrict(const Vector& b) const {
  if (rule_ == FixedParticleRule::kElimination) return free_.restrict(b);
  Vector out = b;
  zero_fixed(forces_->model(), out);
  return out;
}

void StepMatrix::add_solution(const Vector& x, Vector& full) const {
  if (rule_ == FixedParticleRule::kElimination) {
    free_.add_expanded(x, full);
  } else {
    full += x;
  }
}

}  // namespace fosssim
