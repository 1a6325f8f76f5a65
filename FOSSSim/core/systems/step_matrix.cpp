#include "core/systems/step_matrix.h"

#include <algorithm>
#include <cassert>

#include "core/force_evaluation.h"
#include "core/forces/spring_force.h"

namespace fosssim {

StepMatrix::StepMatrix(const ForceSet& forces, FixedParticleRule rule, bool definite_hessian)
    : forces_(&forces),
      rule_(rule),
      definite_hessian_(definite_hessian),
      free_(forces.model().fixed, forces.model().dim),
      any_fixed_(forces.model().has_fixed_particles()),
      pattern_(make_pattern()) {}

int StepMatrix::size() const {
  return rule_ == FixedParticleRule::kElimination ? free_.num_dofs() : forces_->model().num_dofs();
}

HessianPattern StepMatrix::make_pattern() const {
  const SceneModel& model = forces_->model();
  std::vector<int> map(static_cast<std::size_t>(model.num_particles()));
  for (int p = 0; p < model.num_particles(); ++p) {
    if (rule_ == FixedParticleRule::kElimination) {
      map[p] = free_.of_particle(p);
    } else {
      map[p] = model.fixed[p] ? -1 : p;  // a fixed particle keeps only its unit diagonal
    }
  }
  return HessianPattern(model.dim, std::move(map), size());
}

const SparseMatrix& StepMatrix::assemble(const Vector& q, const Vector& v, double h,
                                         const Vector* u, Vector* rhs) {
  const ForceInput in{q, v, forces_->model().mass, definite_hessian_};
  if (!recorded_) record(in);
  if (pattern_usable_ && !scatter(in, h, u, rhs, matrix_)) {
    record(in);  // the forces write other blocks than before
    if (pattern_usable_ && scatter(in, h, u, rhs, matrix_)) return matrix_;
    pattern_usable_ = false;
  }
  if (!pattern_usable_) build_from_triplets(in, h, u, rhs, matrix_);
  return matrix_;
}

const SparseMatrix& StepMatrix::assemble_definite(const Vector& q, const Vector& v, double h) {
  const ForceInput in{q, v, forces_->model().mass, true};
  if (!recorded_) record(in);
  if (!pattern_usable_ || !scatter(in, h, nullptr, nullptr, definite_)) {
    build_from_triplets(in, h, nullptr, nullptr, definite_);
  }
  return definite_;
}

void StepMatrix::record(const ForceInput& in) {
  pattern_.clear();
  HessianBuilder builder = HessianBuilder::recording(pattern_);
  for (const Force* force : *forces_) force->add_hessian_x(in, builder);
  pattern_.mark_second_pass();
  for (const Force* force : *forces_) force->add_hessian_v(in, builder);
  pattern_usable_ = pattern_.finish(matrix_);
  definite_ = SparseMatrix();
  recorded_ = true;
}

bool StepMatrix::scatter(const ForceInput& in, double h, const Vector* u, Vector* rhs,
                         SparseMatrix& out) {
  if (out.nonZeros() != matrix_.nonZeros() || out.rows() != matrix_.rows()) out = matrix_;
  std::fill_n(out.valuePtr(), out.nonZeros(), -0.0);
  double* values = out.valuePtr();
  if (rhs != nullptr) saved_rhs_ = *rhs;
  HessianBuilder builder = HessianBuilder::scattering(pattern_, values);
  builder.set_scale(h * h);
  builder.set_product(u, rhs);
  for (const Force* force : *forces_) force->add_hessian_x(in, builder);
  builder.set_product(nullptr, nullptr);
  builder.set_scale(h);
  pattern_.begin_second_pass();
  for (const Force* force : *forces_) force->add_hessian_v(in, builder);
  if (!pattern_.scattered_all()) {
    if (rhs != nullptr) *rhs = saved_rhs_;
    return false;
  }
  const SceneModel& model = forces_->model();
  for (int dof = 0; dof < model.num_dofs(); ++dof) {
    if (rule_ == FixedParticleRule::kIdentityRows) {
      values[pattern_.diagonal_slot(dof)] += model.is_fixed_dof(dof) ? 1.0 : model.mass[dof];
    } else if (const int f = free_.of_dof(dof); f >= 0) {
      values[pattern_.diagonal_slot(f)] += model.mass[dof];
    }
  }
  return true;
}

const SparseMatrix& StepMatrix::assemble_from_triplets(const Vector& q, const Vector& v, double h,
                                                       const Vector* u, Vector* rhs) {
  const ForceInput in{q, v, forces_->model().mass, definite_hessian_};
  build_from_triplets(in, h, u, rhs, matrix_);
  recorded_ = false;  // matrix_ may no longer hold the recorded pattern
  return matrix_;
}

void StepMatrix::build_from_triplets(const ForceInput& in, double h, const Vector* u, Vector* rhs,
                                     SparseMatrix& out) {
  const SceneModel& model = forces_->model();
  scratch_.clear();
  scratch_.set_scale(h * h);
  scratch_.set_product(u, rhs);
  for (const Force* force : *forces_) force->add_hessian_x(in, scratch_);
  scratch_.set_product(nullptr, nullptr);
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
  out = scratch_.build(size());
}

const Eigen::MatrixXd& StepMatrix::assemble_course(const Vector& q, const Vector& v, double h) {
  assert(rule_ == FixedParticleRule::kIdentityRows);
  const SceneModel& model = forces_->model();
  const int n = model.num_dofs();
  const ForceInput in{q, v, model.mass, definite_hessian_};
  dense_.setZero(n, n);
  // Adds the builder's values entry by entry, in the order the forces wrote them.
  const auto add_written = [this]() {
    for (const Triplet& t : scratch_.triplets()) {
      dense_(t.row(), t.col()) = dense_(t.row(), t.col()) + t.value();
    }
    scratch_.clear();
  };
  scratch_.clear();
  scratch_.set_scale(1.0);
  scratch_.set_product(nullptr, nullptr);
  // A 2D spring writes its blocks as the course does (SpringForce::add_course_hessian_x/_v):
  // elastic and damping apart, and its hessV even when undamped. Other forces' blocks are
  // already the course's.
  for (const Force* force : *forces_) {
    if (const auto* spring = dynamic_cast<const SpringForce<2>*>(force)) {
      spring->add_course_hessian_x(in, scratch_);
    } else {
      force->add_hessian_x(in, scratch_);
    }
  }
  add_written();
  dense_ *= h;
  for (const Force* force : *forces_) {
    if (const auto* spring = dynamic_cast<const SpringForce<2>*>(force)) {
      spring->add_course_hessian_v(in, scratch_);
    } else {
      force->add_hessian_v(in, scratch_);
    }
  }
  add_written();
  dense_ *= h;
  for (int dof = 0; dof < n; ++dof) dense_(dof, dof) = dense_(dof, dof) + model.mass[dof];
  if (any_fixed_) {
    for (int dof = 0; dof < n; ++dof) {
      if (!model.is_fixed_dof(dof)) continue;
      dense_.row(dof).setZero();
      dense_.col(dof).setZero();
      dense_(dof, dof) = 1.0;
    }
  }
  return dense_;
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
