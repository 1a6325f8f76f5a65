#pragma once

#include <optional>
#include <string>

#include "core/force.h"
#include "core/forces/rigid_body_spring_force.h"

namespace fosssim {

/// The mouse's pull on a rigid body: while a body is grabbed, exactly the rigid-body spring of
/// stiffness k and rest length 0 from the grabbed point p of body b (body space) to a world
/// point t (RigidBodySpringForce(b, p, −1, t, k, 0), docs/rigid-bodies.md, 'Forces'):
///   U = ½ k |R(θ_b) p + X_b − t|²,  F_b = −k d,  τ_b = −(R p) × (k d),  d = R p + X − t.
/// No new physics: the spring's energy, gradient and exact Hessian, with the spring's l = 0
/// case (no force when the point is on the target). It adds nothing until grab() and after
/// release(). Like DragSpringForce it belongs to no scene model: the window owns it, hands it to
/// the simulation as an interaction force (core/force_set.h) and changes it between steps.
class RigidBodyDragForce final : public Force {
 public:
  /// Starts pulling point `body_point` (body space) of body `body` toward `target` with
  /// stiffness k (N/m, > 0).
  void grab(int body, const Vec<2>& body_point, const Vec<2>& target, double k);
  /// Moves the point the grabbed body is pulled toward; ignored when nothing is grabbed.
  void move_target(const Vec<2>& target);
  /// Lets go: the force adds nothing until the next grab.
  void release();

  bool active() const { return body_ >= 0; }
  /// The grabbed body, or −1.
  int body() const { return body_; }
  const Vec<2>& body_point() const { return body_point_; }
  const Vec<2>& target() const { return target_; }
  double stiffness() const { return k_; }

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override;

 private:
  int body_ = -1;
  Vec<2> body_point_ = Vec<2>::Zero();
  Vec<2> target_ = Vec<2>::Zero();
  double k_ = 0.0;
  std::optional<RigidBodySpringForce> spring_;  ///< the spring of the current grab and target
};

}  // namespace fosssim
