#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"
#include "core/spring_terms.h"

namespace fosssim {

/// A Hookean spring with internal damping between particles i and j (docs/forces.md, 'Spring').
///
/// With d = x_j - x_i, l = |d|, n = d/l, P = n nᵀ and dv = v_j - v_i:
///   U = ½ k (l - l0)²,  F_i = k (l - l0) n + b (n·dv) n,  F_j = -F_i.
///   hessX = k [P + ((l - l0)/l)(I - P)] + (b/l)[n dvᵀ + (n·dv) I](I - P)   (pair pattern)
///   hessV = b P                                                           (pair pattern)
/// The damping term's position Jacobian is not symmetric. A zero-rest-length spring
/// (l0 = 0, b = 0) stays defined at l = 0, where F_i = k d and hessX = k I. When the Hessian
/// builder asks for definite blocks, (l - l0)/l is clamped at 0 (see spring_hessian_x).
template <int D>
class SpringForce final : public Force {
 public:
  /// i, j: particle indices; k: stiffness (N/m); l0: rest length (m); b: damping (N·s/m).
  SpringForce(int i, int j, double k, double l0, double b) : i_(i), j_(j), k_(k), l0_(l0), b_(b) {}

  void add_energy(const ForceInput& in, double& energy) const override;
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const override;
  /// hessX as the course's dense assembly adds it (StepMatrix::assemble_course): the elastic
  /// block, then the damping block (even for b = 0), so that each entry's sum rounds as the
  /// course's; add_hessian_x adds their sum as one block.
  void add_course_hessian_x(const ForceInput& in, HessianBuilder& hessian) const;
  /// hessV as the course adds it: the block b P even for b = 0 (zeros), where add_hessian_v
  /// adds nothing.
  void add_course_hessian_v(const ForceInput& in, HessianBuilder& hessian) const;
  bool is_conservative() const override { return b_ == 0.0; }
  bool has_symmetric_jacobians() const override { return b_ == 0.0; }
  std::string label() const override;
  /// Local/global: one spring, its damping as Laplacian damping (core/integrators/local_global.h).
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kSprings; }
  void append_local_global_springs(std::vector<SpringTerm>& springs) const override {
    springs.push_back({i_, j_, k_, l0_, b_});
  }

 private:
  /// x_j - x_i.
  Vec<D> extension(const Vector& q) const;
  /// v_j - v_i, or zero for an undamped spring (its velocity does not enter).
  Vec<D> relative_velocity(const Vector& v) const;

  int i_, j_;
  double k_, l0_, b_;
};

/// Reads `springforce edge k l0 [b]`; rejects a spring whose edge has coincident ends.
std::unique_ptr<Force> make_spring_force(ForceParameters& params, const ForceContext& context);

}  // namespace fosssim
