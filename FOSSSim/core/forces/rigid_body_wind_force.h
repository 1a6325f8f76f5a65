#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

struct RigidBodies;

/// Wind on the edges of every rigid body, fixed ones too (docs/rigid-bodies.md, 'Forces'):
/// each edge (vertex e → e+1, world vector E, length L, unit normal n = perp(E)/L) is sampled
/// at the midpoints p_j of P equal pieces, and each sample pushes with
///   f = (β (1/P) L ((w − v(p_j))·n)) n,  F += f,  τ += (p_j − X) × f,
/// where v(p) = V + ω × (p − X). Not conservative (no energy). Linear in the velocities: hessV
/// is exact (Σ c u uᵀ with u = (n, (p_j − X) × n), c = β L / P); the position Jacobian is left
/// out (has_jacobian() is false), as rigid bodies are stepped by explicit methods only.
class RigidBodyWindForce final : public Force {
 public:
  RigidBodyWindForce(std::shared_ptr<const RigidBodies> bodies, double beta, const Vec<2>& wind,
                     int points_per_edge);

  void add_energy(const ForceInput&, double&) const override {}
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput&, HessianBuilder&) const override {}
  void add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const override;
  bool is_conservative() const override { return false; }
  bool has_potential() const override { return false; }
  bool has_jacobian() const override { return false; }
  std::string label() const override { return "rigidbodywindforce"; }

 private:
  /// Calls visit(body, sample point, normal, c = β L / P) for every sample of every edge.
  template <typename Visit>
  void for_each_sample(const Vector& q, Visit visit) const;

  std::shared_ptr<const RigidBodies> bodies_;
  double beta_;
  Vec<2> wind_;  ///< the wind's velocity w
  int points_per_edge_;
};

/// Reads `rigidbodywindforce beta fx fy pointsperedge` (fx fy: the wind's velocity).
std::unique_ptr<Force> make_rigid_body_wind_force(ForceParameters& params,
                                                  const ForceContext& context);

/// At most this many samples per edge: the count is a loop bound read from the file.
inline constexpr int kMaxWindPointsPerEdge = 1000000;

}  // namespace fosssim
