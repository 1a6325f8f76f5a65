#pragma once
// Finite-difference checks of a force's gradient and Hessians, usable on any scene.

#include <string>
#include <vector>

#include "core/force.h"
#include "core/scene_model.h"
#include "core/types.h"

namespace fosssim {

enum class Derivative {
  kGradient,  ///< gradE·u against the central difference of U along u (at v = 0)
  kHessianX,  ///< hessX·u against the central difference of gradE along u in q
  kHessianV,  ///< hessV·u against the central difference of gradE along u in v
};

const char* derivative_name(Derivative which);

struct DerivativeCheckOptions {
  double step = 1e-6;             ///< finite-difference step ε in q, in the units of q
  double velocity_step = 1e-4;    ///< finite-difference step in v for hessV, in the units of v
  int random_directions = 8;      ///< random unit directions u checked
  int all_directions_up_to = 60;  ///< also check every unit vector e_k when #DOFs ≤ this
  unsigned seed = 1;
  double relative_tolerance = 1e-6;  ///< pass when error ≤ rtol·scale + the round-off floor
};

/// The worst direction found for one derivative of one force.
struct DerivativeCheck {
  std::string force;
  Derivative which = Derivative::kGradient;
  double absolute_error = 0.0;  ///< ‖analytic·u - finite difference‖
  double scale = 0.0;  ///< max(‖analytic·u‖, ‖finite difference‖) in that direction
  /// Round-off level of the comparison: ε_machine·1e3·(|U|/ε + ‖gradE‖ + |q|_∞‖hessX u‖) for
  /// the gradient, ε_machine·1e3·(‖gradE‖/ε + |x|_∞‖H‖) for a Hessian H in x = q or v.
  double noise_floor = 0.0;
  /// error / (rtol·scale + noise_floor) in the worst direction; the check passes when ≤ 1.
  /// Infinite when a derivative or its estimate is NaN.
  double allowance_used = 0.0;
  bool passed() const { return allowance_used <= 1.0; }
  /// Error relative to the scale, 0 when both sides vanish.
  double relative_error() const { return scale > 0.0 ? absolute_error / scale : 0.0; }
  /// True when the derivative and its estimate are both within round-off of zero in the worst
  /// direction (hessV of an undamped spring): a relative error means nothing there.
  bool vanishes() const { return scale <= noise_floor; }
};

/// Checks gradient, hessX and hessV of one force at (q, v) by Richardson-extrapolated central
/// differences (error O(ε⁴)) along random and unit directions. The differences are compared
/// with the analytic derivative applied to the steps actually taken between the rounded points
/// x ± εu, so short distances far from the origin are checked as accurately as near it. The
/// gradient is checked against the energy at v = 0, and only for forces with a potential
/// (Force::has_potential); hessX only for forces that have one (Force::has_jacobian).
std::vector<DerivativeCheck> check_force_derivatives(const Force& force, const Vector& q,
                                                     const Vector& v, const Vector& mass,
                                                     const DerivativeCheckOptions& options);

/// Runs check_force_derivatives for every force of the model, its contact force included.
std::vector<DerivativeCheck> check_model_derivatives(const SceneModel& model, const Vector& q,
                                                     const Vector& v,
                                                     const DerivativeCheckOptions& options);

/// A finite-difference step suited to the configuration: 1e-4 times the shortest nonzero
/// distance between two particles (sampled when there are many), at most 1e-4.
double suggest_finite_difference_step(const Vector& q, int dim);

}  // namespace fosssim
