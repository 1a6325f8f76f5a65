#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// Linear drag on every particle (docs/forces.md, 'Drag').
///   F_p = -b v_p;  hessV = b I;  no energy, no position dependence.
template <int D>
class DragDampingForce final : public Force {
 public:
  explicit DragDampingForce(double b) : b_(b) {}

  void add_energy(const ForceInput&, double&) const override {}
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput&, HessianBuilder&) const override {}
  void add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const override;
  bool is_conservative() const override { return false; }
  std::string label() const override { return "dragdamping"; }
  /// Local/global: explicit (the drag of vⁿ, held through the step).
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kExplicit; }

 private:
  double b_;  ///< drag coefficient, N·s/m
};

/// Reads `dragdamping b`.
std::unique_ptr<Force> make_drag_damping_force(ForceParameters& params,
                                               const ForceContext& context);

}  // namespace fosssim
