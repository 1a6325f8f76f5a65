#pragma once
// Continuous-time detection: whether and when two objects moving linearly over a step touch
// while approaching (course-compatible polynomials and interval logic, docs/collisions.md).

#include <optional>
#include <vector>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/polynomial.h"
#include "core/collisions/proximity.h"
#include "core/scene_model.h"

namespace fosssim {

/// The polynomials in t ∈ [0, 1] of `pair` moving linearly from xs to xe (x(t) = xs + t Δx,
/// Δx = xe - xs), all positive exactly when the objects overlap and approach, in the course's
/// order (docs/collisions.md lists them):
///   particle-particle, particle-half-plane and particle-sphere (a particle at rest):
///   overlap (quadratic), approach (linear);
///   particle-edge: overlap with the edge's line times ‖edge(t)‖² (quartic), α(t) > 0 and
///   α(t) < 1 (quadratics), approach (the course's quintic, whose t³ coefficient has -2FGQ
///   where the exact expansion has -2FHQ: course-compatible, kept on purpose).
template <int D>
std::vector<Polynomial> swept_polynomials(const SceneModel& model, const CandidatePair& pair,
                                          const Vector& xs, const Vector& xe);

/// A collision found by continuous-time detection.
template <int D>
struct SweptCollision {
  double time = 0.0;         ///< the first time in [0, 1] at which all polynomials are positive
  /// The shortest vector at that time, unnormalised; alpha is the response's (clamped).
  Separation<D> separation;
};

/// Detects `pair` over the step from xs to xe: the first time t ≤ 1 (inclusive) at which all of
/// its polynomials are positive, and the separation at time t: in 2D in the course's arithmetic
/// (course_swept_separation: an edge's normal from the unclamped α, and an exactly zero one is
/// no collision), in 3D separation() at the positions xs + t Δx. Appends the pair's (stripped)
/// polynomials to `log` when given, whether or not it collides.
template <int D>
std::optional<SweptCollision<D>> detect_swept(const SceneModel& model, const CandidatePair& pair,
                                              const Vector& xs, const Vector& xe,
                                              std::vector<Polynomial>* log);

}  // namespace fosssim
