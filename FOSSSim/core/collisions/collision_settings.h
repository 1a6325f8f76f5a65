#pragma once
// What a scene says about contact: half-planes and the collision method with its parameters.

#include <string_view>

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

/// How a scene handles contact (docs/collisions.md).
enum class CollisionMethod {
  kNone,            ///< nothing collides
  kSimple,          ///< discrete detection after each step and impulses (Gauss-Seidel)
  kPenalty,         ///< a penalty force, summed after every other force
  kContinuousTime,  ///< swept detection over the step and impulses (Gauss-Seidel)
  kHybrid,          ///< penalty force, Jacobi passes of swept impulses, then rigid impact zones
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

/// The <collision> element and its parameters, with the course's defaults.
struct CollisionSettings {
  CollisionMethod method = CollisionMethod::kNone;
  double cor = 1.0;          ///< coefficient of restitution (simple, continuous-time, hybrid)
  double stiffness = 100.0;  ///< penalty k (hybrid's default is 10)
  double thickness = 0.01;   ///< penalty thickness T (hybrid's default is 0.1)
  /// Hybrid: the most impulse passes before the geometric stage; ≤ 0 skips them.
  int max_iterations = 10;
  PairDetection detection = PairDetection::kDefault;
  PenaltyJacobian penalty_jacobian = PenaltyJacobian::kNone;

  /// True for the methods that add a penalty force to the model.
  bool has_penalty_force() const {
    return method == CollisionMethod::kPenalty || method == CollisionMethod::kHybrid;
  }
  /// True for the methods that run a response stage after the integrator.
  bool has_response_stage() const {
    return method == CollisionMethod::kSimple || method == CollisionMethod::kContinuousTime ||
           method == CollisionMethod::kHybrid;
  }
};

/// The scene-file name of a method ("continuous-time").
std::string_view collision_method_name(CollisionMethod method);

}  // namespace fosssim
