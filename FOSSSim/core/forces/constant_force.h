#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// The same force f on every particle, not scaled by mass (docs/forces.md, 'Constant force').
///   U = -Σ_p f·x_p,  F_p = f;  both Hessians are zero.
template <int D>
class ConstantForce final : public Force {
 public:
  explicit ConstantForce(const Vec<D>& f) : f_(f) {}

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput&, HessianBuilder&) const override {}
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override { return "constantforce"; }
  /// Local/global: explicit, and exact there (the force does not depend on the state).
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kExplicit; }

 private:
  Vec<D> f_;  ///< force, N
};

/// Reads `constantforce fx fy [fz]`.
std::unique_ptr<Force> make_constant_force(ForceParameters& params, const ForceContext& context);

}  // namespace fosssim
