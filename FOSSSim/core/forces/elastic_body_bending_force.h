#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// The course's Theme 4 bending force around a hinge, in the plane (docs/forces.md, 'Elastic
/// bodies'). Particles x1, x2 (the hinge), x3; edges e1 = x2 - x1, e2 = x3 - x2.
///
///   θ = atan2(e1 × e2, e1 · e2) ∈ [-π, π], the signed turn from e1 to e2 (counter-clockwise
///   positive; a straight polyline has θ = 0), taken as is: no wrapping, so U jumps where θ
///   crosses ±π, as in the course's program.
///   U = α (θ - θ0)² / (2 L),  L = |ē1| + |ē2| the edge lengths at the scene's initial positions.
///   ∇θ: g1 = R e1 / |e1|², g3 = R e2 / |e2|² with R(a, b) = (-b, a);
///       ∂θ/∂x1 = g1, ∂θ/∂x2 = -g1 - g3, ∂θ/∂x3 = g3.
///   ∇U = (α / L)(θ - θ0) ∇θ,  hessX = (α / L)[∇θ ∇θᵀ + (θ - θ0) ∇²θ] (exact),  hessV = 0,
///   where ∇²θ has the blocks [[-J1, J1, 0], [J1, -J1 + J2, -J2], [0, -J2, J2]] in the order
///   (x1, x2, x3), J(e) = d(R e / |e|²)/de = [[2ab, b² - a²], [b² - a², -2ab]] / |e|⁴ for
///   e = (a, b), J1 = J(e1), J2 = J(e2).
/// The signed angle needs a plane: this force exists in 2D only (a dim="3" scene is refused at
/// load). hessX is indefinite in general; with ForceInput::definite_hessian the 6×6 element block
/// is projected onto the positive semi-definite matrices (its negative eigenvalues set to 0:
/// core/forces/psd_projection.h).
class ElasticBodyBendingForce final : public Force {
 public:
  /// i1, i2 (hinge), i3: particle indices; alpha: bending modulus (N·m²), ≥ 0; theta0: rest
  /// angle (rad); rest_length: L > 0 (m).
  ElasticBodyBendingForce(int i1, int i2, int i3, double alpha, double theta0, double rest_length)
      : i1_(i1), i2_(i2), i3_(i3), alpha_(alpha), theta0_(theta0), rest_length_(rest_length) {}

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override;
  /// Local/global: explicit. U is quadratic in the angle, not in a projection of positions
  /// onto a shape, so it has no constant matrix (docs/integrators.md, 'Local/global').
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kExplicit; }
  /// One hinge, its strain θ - θ0, its density U / L.
  void append_elements(const Vector& q, std::vector<ForceElement>& elements) const override;

  /// θ of the current positions, as above.
  double angle(const Vector& q) const;

 private:
  int i1_, i2_, i3_;
  double alpha_, theta0_, rest_length_;
};

/// Reads `elasticbodybendingforce i1 i2 i3 alpha theta0`; L from the initial positions. Rejects
/// 3D scenes, repeated indices, alpha < 0, and a hinge whose edges start with zero length.
std::unique_ptr<Force> make_elastic_body_bending_force(ForceParameters& params,
                                                       const ForceContext& context);

}  // namespace fosssim
