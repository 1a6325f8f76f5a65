#pragma once

#include <string>
#include <vector>

#include "core/force.h"
#include "core/spring_terms.h"

namespace fosssim {

/// Many Hookean springs with internal damping held in one force, for meshes: the same energy,
/// forces and Jacobians as one SpringForce per spring (spring_kernel.h, docs/forces.md), evaluated
/// in one loop over a flat array instead of one virtual call and one heap object per spring.
///
/// Per spring s = (i, j, k, l0, b), with d = x_j - x_i, l = |d|, n = d/l, dv = v_j - v_i:
///   U_s = ½ k (l - l0)²,  F_i = k (l - l0) n + b (n·dv) n,  F_j = -F_i.
/// Springs are summed in array order.
template <int D>
class SpringSetForce final : public Force {
 public:
  /// springs: particle indices, stiffness (N/m), rest length (m) and damping (N·s/m) of each;
  /// label: names the set in messages ("clothmesh 0", say).
  SpringSetForce(std::vector<SpringTerm> springs, std::string label);

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const override;
  bool is_conservative() const override { return !damped_; }
  bool has_symmetric_jacobians() const override { return !damped_; }
  std::string label() const override;
  /// Local/global: its springs, in order, implicit.
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kSprings; }
  void append_local_global_springs(std::vector<SpringTerm>& springs) const override {
    springs.insert(springs.end(), springs_.begin(), springs_.end());
  }
  /// The springs, in summation order.
  const std::vector<SpringTerm>& springs() const { return springs_; }

 private:
  std::vector<SpringTerm> springs_;
  std::string label_;
  bool damped_ = false;  ///< any spring with b ≠ 0
};

}  // namespace fosssim
