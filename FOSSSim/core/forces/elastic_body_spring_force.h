#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// The course's Theme 4 spring, written with a modulus (docs/forces.md, 'Elastic bodies'): a
/// spring between particles i and j of stiffness k = α / l0, where α is the modulus (N) and l0
/// the rest length (m) of the declaration, not the initial distance.
///
/// With d = x_i - x_j, l = |d|, n = d/l:
///   U = (α / (2 l0)) (l - l0)²,  ∇_i U = k (l - l0) n,  ∇_j U = -∇_i U,
///   hessX = k [n nᵀ + (1 - l0/l)(I - n nᵀ)]   (pair pattern);  hessV = 0.
/// The gradient is evaluated in the course program's order (k first, then c = k (l - l0), then
/// c · (d / l)), so that trajectories match its bits. When the Hessian builder asks for definite
/// blocks, the transverse factor 1 - l0/l is clamped at 0 as for the Theme 1 spring.
template <int D>
class ElasticBodySpringForce final : public Force {
 public:
  /// i, j: distinct particle indices; alpha: modulus (N), ≥ 0; l0: rest length (m), > 0.
  ElasticBodySpringForce(int i, int j, double alpha, double l0)
      : i_(i), j_(j), alpha_(alpha), l0_(l0) {}

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override;
  /// Local/global: one spring of stiffness α / l0, implicit like the Theme 1 spring.
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kSprings; }
  void append_local_global_springs(std::vector<SpringTerm>& springs) const override {
    springs.push_back({i_, j_, alpha_ / l0_, l0_, 0.0});
  }

 private:
  int i_, j_;
  double alpha_, l0_;
};

/// Reads `elasticbodyspringforce i1 i2 alpha l0`; rejects i1 = i2, particles that start at the
/// same point, alpha < 0 and l0 ≤ 0.
std::unique_ptr<Force> make_elastic_body_spring_force(ForceParameters& params,
                                                      const ForceContext& context);

}  // namespace fosssim
