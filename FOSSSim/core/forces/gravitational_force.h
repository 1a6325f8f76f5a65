#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// Newtonian attraction between particles i and j (docs/forces.md, 'Newtonian gravity').
///
/// With d = x_j - x_i, l = |d|, n = d/l, P = n nᵀ:
///   U = -G m_i m_j / l,  F_i = (G m_i m_j / l²) n,  F_j = -F_i,
///   hessX = (G m_i m_j / l³)(I - 3P)   (pair pattern);  hessV = 0.
template <int D>
class GravitationalForce final : public Force {
 public:
  /// i, j: particle indices; G: gravitational constant (N·m²/kg²).
  GravitationalForce(int i, int j, double G) : i_(i), j_(j), G_(G) {}

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override;
  /// Local/global: explicit (not a spring: the attraction at qⁿ, held through the step).
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kExplicit; }

 private:
  int i_, j_;
  double G_;
};

/// Reads `gravitationalforce i j G`; rejects i = j and coincident particles.
std::unique_ptr<Force> make_gravitational_force(ForceParameters& params,
                                                const ForceContext& context);

}  // namespace fosssim
