#pragma once
// The course's floating-point arithmetic of continuous-time handling in 2D: the normal at the
// collision time and the response, operation for operation as the course's program does them
// (docs/collisions.md, "Continuous time in the course's arithmetic"). The collision time itself
// comes from FOSSSim's root finder, which is not the course's.

#include <optional>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/proximity.h"
#include "core/scene_model.h"
#include "core/state.h"

namespace fosssim {

/// The separation of `pair` at the time t ∈ [0, 1] of a step moving each particle k linearly
/// from xs_k by Δx_k = X_k - xs_k, in the course's order of operations (each step one rounding,
/// as parenthesised; y_k = Δx_k×t + xs_k):
///   particle-particle   n = y_j - y_i;
///   particle-edge (a, b), without forming y_a:
///     E = ((Δx_b×t + xs_b) - xs_a) - Δx_a×t,  W = ((Δx_i×t + xs_i) - xs_a) - Δx_a×t,
///     α = (W·E) ÷ (E·E), NOT clamped,  n = (((E×α) + y_a) - xs_i) - Δx_i×t,
///     and an n that is exactly zero is no collision (nullopt);
///   particle-half-plane (P, N as written)
///     τ = (((P - xs_i) - Δx_i×t)·N) ÷ (N·N),  n = (N_x×τ, τ×N_y).
/// The returned alpha is what the response uses: for an edge, α' = ((y_i - y_a)·u) ÷ (u·u) with
/// u = y_b - y_a, clamped as the course clamps it (α' > 0 ? min(α', 1) : 0, so NaN gives 0).
/// distance is √(n·n), radii the sum of the radii (the particle's alone for a half-plane).
std::optional<Separation<2>> course_swept_separation(const SceneModel& model,
                                                     const CandidatePair& pair, const Vector& xs,
                                                     const Vector& X, double t);

/// Answers one continuous-time collision of `pair` along n (course_swept_separation's) in the
/// course's arithmetic, changing the end positions X = state.q and velocities V = state.v of
/// the step that started at xs, with step h and coefficient of restitution cor:
///   ṽ_k = (X_k - xs_k)×(1/h) (the displacement velocities as they are when this response
///   starts), n̂ = n×(1/√(n·n)), c = (1 + cor)×0.5, S = s×(c + c);
///   particle-particle, s = (ṽ_j - ṽ_i)·n̂, D_i = (M_i ÷ M_j) + 1, D_j = (M_j ÷ M_i) + 1:
///     V_i = n̂×(S ÷ D_i) + V_i,  X_i = n̂×((h×S) ÷ D_i) + X_i,
///     V_j = V_j - n̂×(S ÷ D_j),  X_j = X_j - n̂×((h×S) ÷ D_j);
///   particle-edge (a, b), ṽ_e = (ṽ_b - ṽ_a)×α + ṽ_a, s = (ṽ_e - ṽ_i)·n̂, β = 1 - α, and the
///   denominators of the simple impulses (impulses.h) D_i, D_a, D_b:
///     V_i = n̂×(S ÷ D_i) + V_i,        X_i = n̂×((h×S) ÷ D_i) + X_i,
///     V_a = V_a - n̂×((β×S) ÷ D_a),    X_a = X_a - n̂×(((h×β)×S) ÷ D_a),
///     V_b = V_b - n̂×((S×α) ÷ D_b),    X_b = X_b - n̂×(((h×α)×S) ÷ D_b);
///   particle-half-plane, s = ṽ_i·n̂:  V_i = V_i - n̂×S,  X_i = X_i - n̂×(((h + h)×c)×s).
/// M is +∞ for a fixed particle, which is left alone, except against a half-plane: the course
/// bounces a fixed particle off a half-plane too. Returns the particles it moved.
MovedParticles respond_course_swept(const SceneModel& model, const CandidatePair& pair,
                                    const Separation<2>& separation, const Vector& xs, double h,
                                    double cor, State& state);

}  // namespace fosssim
