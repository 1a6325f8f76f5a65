#pragma once
// What a scene says about contact: half-planes and the contact method with its parameters.

#include <array>
#include <limits>
#include <string_view>

#include "core/collisions/contact_registry.h"
#include "core/integrators/integrator_options.h"
#include "core/types.h"

namespace fosssim {

/// A solid half-plane (a half-space in 3D): the points y with (y - point)·normal ≤ 0. The normal
/// is kept exactly as the scene gives it, unnormalised: its length never matters, but the
/// course's formulas divide by normal·normal, and normalising would change their last bits.
struct HalfPlane {
  Vector point;   ///< a point on the boundary, size dim
  Vector normal;  ///< points out of the solid, size dim; need not be unit length
};

/// A solid ball, at rest, that particles collide with (3D scenes only): the points y with
/// ‖y - center‖ ≤ radius. To a particle it is a particle of infinite mass that never moves.
struct Sphere {
  Vector center;        ///< size dim
  double radius = 0.0;  ///< > 0
};

/// How candidate pairs are found (<collisiondetection type>; docs/collisions.md, "Broad
/// phase").
enum class PairDetection {
  /// No <collisiondetection>: FOSSSim's grid wherever it gives the results of all pairs
  /// bit for bit (penalty and simple in 2D, everything in 3D), all pairs for 2D
  /// continuous-time and hybrid handling, whose polynomial logs list every pair.
  kDefault,
  kAllPairs,  ///< type="allpairs": every pair, in the course's order
  kContest,   ///< type="contest": FOSSSim's grid (core/collisions/grid_pairs.h) for every method
};

/// How the penalty force enters the matrices of implicit integrators.
enum class PenaltyJacobian {
  /// The course's semantics: the penalty force has no Jacobian and appears only in right-hand
  /// sides, so stiff contact under implicit Euler is no more stable than under explicit Euler.
  kNone,
  /// FOSSSim's option: the exact Jacobian of the penalty force, so implicit Euler is stable
  /// for stiff contact too.
  kExact,
};

/// The settings of the particle methods (Theme 2's <collision> attributes), declared once for the
/// entries that read them: each method lists those it reads, in the course's reading order
/// (COR, k, thickness, penalty-jacobian, maxiters), with its own defaults.
namespace particle_contact_options {
/// A number the course accepts whatever its value (a suspicious one gets a warning).
constexpr OptionSpec any_number(std::string_view name, double default_value,
                                std::string_view help) {
  return OptionSpec::number(name, default_value, -std::numeric_limits<double>::infinity(), false,
                            help);
}
constexpr OptionSpec restitution(std::string_view help) { return any_number("COR", 1.0, help); }
constexpr OptionSpec stiffness(double default_value) {
  return any_number("k", default_value, "penalty stiffness k, N/m (a negative one pulls together)");
}
constexpr OptionSpec thickness(double default_value) {
  return any_number("thickness", default_value,
                    "penalty thickness T, m: the force acts within the radii plus T");
}
inline constexpr std::array<std::string_view, 2> kPenaltyJacobianChoices = {"none", "exact"};
constexpr OptionSpec penalty_jacobian() {
  OptionSpec spec = OptionSpec::choice(
      "penalty-jacobian", kPenaltyJacobianChoices,
      "how implicit integrators see the penalty force: none (the course's: right-hand sides "
      "only) or exact (its exact Jacobian in the step matrix)");
  spec.values_text = "\"none\" (the course's) or \"exact\"";
  return spec;
}
constexpr OptionSpec max_iterations(double default_value) {
  return any_number("maxiters", default_value,
                    "impulse passes a step before the geometric stage, truncated; <= 0 skips "
                    "them (capped by --max-hybrid-passes)");
}
}  // namespace particle_contact_options

/// How a scene handles contact: the method (a particle scene's <collision>, a rigid-body scene's
/// <rigidbodycollisionhandling>) and its settings, with the course's defaults.
struct CollisionSettings {
  /// The method (an entry of core/collisions/contact_registry.h); "none" without <collision>
  /// (<rigidbodycollisionhandling>).
  const ContactMethod* method = &no_contact_method();
  /// The values of method->options as the scene gave them, defaults for the others: where a
  /// method whose settings are not among the fields below reads them.
  OptionValues options{method->options};
  // The particle methods' settings, which the loader copies from `options` (the fields of the
  // options a method does not have keep these defaults) and their code reads:
  double cor = 1.0;          ///< coefficient of restitution (simple, continuous-time, hybrid)
  double stiffness = 100.0;  ///< penalty k (hybrid's default is 10)
  double thickness = 0.01;   ///< penalty thickness T (hybrid's default is 0.1)
  /// Hybrid: the most impulse passes before the geometric stage; ≤ 0 skips them.
  int max_iterations = 10;
  PairDetection detection = PairDetection::kDefault;
  PenaltyJacobian penalty_jacobian = PenaltyJacobian::kNone;

  /// Switches to `m` with its options at their defaults (the fields above are left as they are).
  void use(const ContactMethod& m) {
    method = &m;
    options = OptionValues(m.options);
  }
};

}  // namespace fosssim
