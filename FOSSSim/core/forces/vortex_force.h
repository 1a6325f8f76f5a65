#pragma once

#include <memory>

#include "core/force.h"
#include "core/force_parameters.h"

namespace fosssim {

/// A vortex centred on particle i that swirls particle j (docs/forces.md, 'Vortex'). Meant for a
/// heavy i and a light j.
///
/// With d = x_j - x_i, l = |d|, n = d/l, dv = v_j - v_i and R the 90° rotation about the
/// vortex axis (R a = (-a_y, a_x) in 2D, R a = axis × a in 3D):
///   w = (kvc / l²)(kbs R n - dv),  F_j = w,  F_i = -w.
/// The course version had no Jacobians; here, with J = dw/dd
///   J = kvc [kbs (R/l³ - 3 R d dᵀ/l⁵) + 2 dv dᵀ/l⁴],
///   hessX = -J   (pair pattern, not symmetric),   hessV = (kvc/l²) I   (pair pattern),
/// so vortices work with the implicit integrators too. No energy.
template <int D>
class VortexForce final : public Force {
 public:
  /// kbs: swirl strength (m²/s); kvc: viscous coupling (N·m/(m/s)); rotation: the D×D matrix R.
  VortexForce(int i, int j, double kbs, double kvc, const Mat<D>& rotation)
      : i_(i), j_(j), kbs_(kbs), kvc_(kvc), rotation_(rotation) {}

  void add_energy(const ForceInput&, double&) const override {}
  void add_gradient(const ForceInput& in, Vector& gradient) const override;
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override;
  void add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const override;
  bool is_conservative() const override { return false; }
  bool has_symmetric_jacobians() const override { return false; }
  bool has_potential() const override { return false; }
  std::string label() const override;
  /// Local/global: explicit (the vortex at (qⁿ, vⁿ), held through the step).
  LocalGlobalRole local_global_role() const override { return LocalGlobalRole::kExplicit; }

 private:
  int i_, j_;
  double kbs_, kvc_;
  Mat<D> rotation_;
};

/// Reads `vortexforce i j kbs kvc`, in 3D also the axis `ax ay az` (default 0 0 1).
std::unique_ptr<Force> make_vortex_force(ForceParameters& params, const ForceContext& context);

}  // namespace fosssim
