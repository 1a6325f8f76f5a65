#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// A uniform gravitational acceleration g on every rigid body, fixed ones too
/// (docs/rigid-bodies.md, 'Forces'). In generalized coordinates (X_x, X_y, θ):
///   U = Σ_b (g_y X_y + g_x X_x)(−M_b),  F_b = M_b g,  τ_b = 0;  both Hessians are zero.
/// The course's Theme 3 order of operations (the energy sums the bodies, then adds the sum).
class RigidBodyGravityForce final : public Force {
 public:
  explicit RigidBodyGravityForce(const Vec<2>& g) : g_(g) {}

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput&, HessianBuilder&) const override {}
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override { return "rigidbodygravityforce"; }

 private:
  Vec<2> g_;  ///< acceleration, m/s²
};

/// Reads `rigidbodygravityforce fx fy` (an acceleration) in a rigid-body scene.
std::unique_ptr<Force> make_rigid_body_gravity_force(ForceParameters& params,
                                                     const ForceContext& context);

/// Fails `params` unless the scene being read is a rigid-body scene (used by the rigid-body
/// forces' factories).
void require_rigid_body_scene(ForceParameters& params, const ForceContext& context);

}  // namespace fosssim
