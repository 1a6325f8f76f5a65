#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// A uniform gravitational acceleration g on every particle (docs/forces.md, 'Simple gravity').
///   U = -Σ_p m_p g·x_p,  F_p = m_p g;  both Hessians are zero.
template <int D>
class SimpleGravityForce final : public Force {
 public:
  explicit SimpleGravityForce(const Vec<D>& g) : g_(g) {}

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput&, HessianBuilder&) const override {}
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override { return "simplegravity"; }
  /// Local/global: explicit, and exact there (the force does not depend on the state).
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kExplicit; }

 private:
  Vec<D> g_;  ///< acceleration, m/s²
};

/// Reads `simplegravity fx fy [fz]`: the acceleration, not a force.
std::unique_ptr<Force> make_simple_gravity_force(ForceParameters& params,
                                                 const ForceContext& context);

}  // namespace fosssim
