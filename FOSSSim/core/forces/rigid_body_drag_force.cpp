#include "core/forces/rigid_body_drag_force.h"

#include <cassert>

namespace fosssim {

void RigidBodyDragForce::grab(int body, const Vec<2>& body_point, const Vec<2>& target, double k) {
  assert(body >= 0 && k > 0.0);
  body_ = body;
  body_point_ = body_point;
  k_ = k;
  move_target(target);
}

void RigidBodyDragForce::move_target(const Vec<2>& target) {
  if (!active()) return;
  target_ = target;
  spring_.emplace(body_, body_point_, -1, target_, k_, 0.0);
}

void RigidBodyDragForce::release() {
  body_ = -1;
  k_ = 0.0;
  spring_.reset();
}

void RigidBodyDragForce::add_energy(const ForceInput& in, double& energy) const {
  if (spring_) spring_->add_energy(in, energy);
}

void RigidBodyDragForce::add_gradient(const ForceInput& in, Vector& gradient) const {
  if (spring_) spring_->add_gradient(in, gradient);
}

void RigidBodyDragForce::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  if (spring_) spring_->add_hessian_x(in, hessian);
}

std::string RigidBodyDragForce::label() const {
  if (!active()) return "rigidbodydragspring (released)";
  return "rigidbodydragspring(" + std::to_string(body_) + ")";
}

}  // namespace fosssim
