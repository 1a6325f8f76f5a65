#pragma once

#include <array>
#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// A spring between a point of one rigid body and a point of another body or of the world
/// (docs/rigid-bodies.md, 'Forces'). An end on body b with body-space attachment p sits at
/// e = R(θ_b) p + X_b; a world end (body −1) at p. With d = e_j − e_i and l = |d|:
///   U = ½ k (l − l0)²,  f = k (l − l0) d / l,
///   body i: F += f, τ += (R_i p_i) × f;  body j: F −= f, τ += (R_j p_j) × (−f).
/// l = l0 = 0 exactly gives no force (the course's special case). Exact Hessian in (X, θ):
/// Jᵀ H_d J plus the curvature terms ∓ (∇_d U)·(R p) on the angles; hessV is zero.
class RigidBodySpringForce final : public Force {
 public:
  /// body_i, body_j: body indices or −1 for a world point; p_i, p_j body-space attachments
  /// (world points for −1); k ≥ any, l0 ≥ any (warned about by the factory when negative).
  RigidBodySpringForce(int body_i, const Vec<2>& p_i, int body_j, const Vec<2>& p_j, double k,
                       double l0);

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override;

  /// The two ends in world coordinates at q (end i, then end j), for pictures.
  std::array<Vec<2>, 2> world_ends(const Vector& q) const {
    return {end(q, body_i_, p_i_).world, end(q, body_j_, p_j_).world};
  }

 private:
  struct End {
    Vec<2> arm;    ///< R(θ) p (the world point itself for −1)
    Vec<2> world;  ///< the end in world coordinates
  };
  End end(const Vector& q, int body, const Vec<2>& p) const;
  Vec<2> separation(const Vector& q, End& ei, End& ej) const;

  int body_i_, body_j_;
  Vec<2> p_i_, p_j_;
  double k_, l0_;
};

/// Reads `rigidbodyspringforce i pix piy j pjx pjy k l0`.
std::unique_ptr<Force> make_rigid_body_spring_force(ForceParameters& params,
                                                    const ForceContext& context);

}  // namespace fosssim
