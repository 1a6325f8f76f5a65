#include "core/forces/drag_spring_force.h"

#include <cassert>

namespace fosssim {

void DragSpringForce::grab(int particle, const Eigen::Vector3d& target, double k) {
  assert(particle >= 0 && k > 0.0);
  particle_ = particle;
  target_ = target;
  k_ = k;
}

void DragSpringForce::move_target(const Eigen::Vector3d& target) {
  if (active()) target_ = target;
}

void DragSpringForce::release() {
  particle_ = -1;
  k_ = 0.0;
}

void DragSpringForce::add_energy(const ForceInput& in, double& energy) const {
  if (!active()) return;
  const auto x = in.q.segment(dim_ * particle_, dim_);
  energy += 0.5 * k_ * (x - target_.head(dim_)).squaredNorm();
}

void DragSpringForce::add_gradient(const ForceInput& in, Vector& gradient) const {
  if (!active()) return;
  const auto x = in.q.segment(dim_ * particle_, dim_);
  gradient.segment(dim_ * particle_, dim_) += k_ * (x - target_.head(dim_));
}

void DragSpringForce::add_hessian_x(const ForceInput&, HessianBuilder& hessian) const {
  if (!active()) return;
  for (int c = 0; c < dim_; ++c) hessian.add_diagonal(dim_ * particle_ + c, k_);
}

std::string DragSpringForce::label() const {
  if (!active()) return "dragspring (released)";
  return "dragspring(" + std::to_string(particle_) + ")";
}

std::optional<AnchorTerm> DragSpringForce::local_global_anchor() const {
  if (!active()) return std::nullopt;
  return AnchorTerm{particle_, k_, target_};
}

}  // namespace fosssim
