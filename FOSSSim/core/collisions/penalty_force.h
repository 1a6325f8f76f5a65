#pragma once
// The penalty force of collisions: a spring pushing apart objects closer than their radii plus
// a thickness (course-compatible, docs/collisions.md).

#include <memory>
#include <string>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/collision_settings.h"
#include "core/collisions/contact_method.h"
#include "core/force.h"
#include "core/scene_model.h"

namespace fosssim {

/// For every candidate pair with separation n (core/collisions/proximity.h), radii R and
/// thickness T (for a sphere R = r_i + its radius), and d = ‖n‖ < R + T: the potential ½ k δ², δ =
/// d - R - T, and with n̂ = n/d
///   particle-particle:  F_i = k δ n̂,  F_j = -k δ n̂;
///   particle-edge:      F_i = k δ n̂,  F_a = -(1-α) k δ n̂,  F_b = -α k δ n̂;
///   particle-half-plane and particle-sphere: F_i = k δ n̂.
/// δ < 0, so every force pushes the particle away from the other object (but a particle whose
/// centre has crossed a half-plane's boundary is pushed further in: the course's unsigned
/// distance). The force is the exact negative gradient of the potential (α is the minimiser of
/// the distance, so its change does not enter to first order).
///
/// Course semantics (PenaltyJacobian::kNone): hessX adds nothing, so implicit integrators use
/// the force only in their right-hand side. With PenaltyJacobian::kExact hessX is the exact
/// Jacobian, k (∇d ∇dᵀ + δ ∇²d), and with ForceInput::definite_hessian only its semi-definite
/// part k ∇d ∇dᵀ. hessV is zero. The course defines no energy; add_energy reports ½ k δ².
/// Which pairs an evaluation of the penalty force sums.
enum class PenaltyPairs {
  kAll,             ///< every pair: the force as every integrator but local/global sees it
  kAmongParticles,  ///< particle-particle and particle-edge pairs only
  kObstacles,       ///< particle-half-plane and particle-sphere pairs only
};

template <int D>
class PenaltyForce final : public Force {
 public:
  /// `model` must outlive the force; it must be the model the force belongs to (its particles,
  /// radii, edges and half-planes).
  PenaltyForce(const SceneModel& model, double stiffness, double thickness,
               PenaltyJacobian jacobian);

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  bool has_jacobian() const override { return jacobian_ == PenaltyJacobian::kExact; }
  std::string label() const override;
  /// Local/global: its obstacle contacts implicit, its particle-edge pairs explicit
  /// (core/integrators/local_global.h).
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kContact; }

  /// add_gradient over the pairs `which` selects only. The local/global solver takes the
  /// obstacles' pairs into its global matrix and the others explicitly (docs/collisions.md).
  void add_gradient(const ForceInput& in, Vector& gradient, PenaltyPairs which) const;
  double stiffness() const { return k_; }
  double thickness() const { return thickness_; }

 private:
  template <typename Visit>
  void for_each_contact(const Vector& q, PenaltyPairs which, Visit&& visit) const;

  const SceneModel* model_;
  double k_;
  double thickness_;
  PenaltyJacobian jacobian_;
  std::unique_ptr<CandidatePairs> pairs_;
};

/// The model's penalty force (model.collisions: method penalty or hybrid), for dimension
/// model.dim.
std::unique_ptr<Force> make_penalty_force(const SceneModel& model);

/// Registry entry: "penalty" (the force alone; hybrid uses the force too).
extern const ContactMethod kPenaltyContactMethod;

}  // namespace fosssim
