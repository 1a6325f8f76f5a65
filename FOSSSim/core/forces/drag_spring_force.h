#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/force.h"

namespace fosssim {

/// A stiff zero-rest-length spring that pulls one particle toward a point, for dragging a
/// particle with the mouse, as in the CSC417 assignment (docs/forces.md, 'The mouse's pulling
/// spring'). With p the grabbed particle and t the target:
///   U = ½ k |x_p - t|²,  F_p = -k (x_p - t),  hessX = k I on block (p, p),  hessV = 0.
/// It adds nothing until grab() and after release(). Unlike other forces it belongs to no scene
/// model: the window owns it and hands it to the simulation as an interaction force
/// (core/force_set.h), and it changes while the simulation runs: the window calls grab,
/// move_target and release between steps, and every integrator sees the change at the next
/// step (the local/global solver takes it as an anchor, core/systems/local_global_system.h).
/// The dimension is a run-time value so that one handle serves 2D and 3D; in 2D the target's z
/// is ignored.
class DragSpringForce final : public Force {
 public:
  /// dim: the scene's dimension, 2 or 3.
  explicit DragSpringForce(int dim) : dim_(dim) {}

  /// Starts pulling particle `particle` toward `target` with stiffness k (N/m, > 0).
  void grab(int particle, const Eigen::Vector3d& target, double k);
  /// Moves the point the grabbed particle is pulled toward; ignored when nothing is grabbed.
  void move_target(const Eigen::Vector3d& target);
  /// Lets go: the force adds nothing until the next grab.
  void release();

  bool active() const { return particle_ >= 0; }
  /// The grabbed particle, or -1.
  int particle() const { return particle_; }
  const Eigen::Vector3d& target() const { return target_; }
  double stiffness() const { return k_; }

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override;
  /// Local/global: an anchor, asked for every step (it changes between steps).
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kAnchor; }
  std::optional<AnchorTerm> local_global_anchor() const override;

 private:
  int dim_;
  int particle_ = -1;
  double k_ = 0.0;
  Eigen::Vector3d target_ = Eigen::Vector3d::Zero();
};

}  // namespace fosssim
