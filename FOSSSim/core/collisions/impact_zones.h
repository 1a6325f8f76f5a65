#pragma once
// Rigid impact zones: the geometric last resort of hybrid collision handling
// (course-compatible, docs/collisions.md).

#include <vector>

#include "core/collisions/candidate_pairs.h"
#include "core/scene_model.h"
#include "core/types.h"

namespace fosssim {

/// A set of particles that moves as one rigid body for the rest of the step. A zone that
/// touched a half-plane is flagged: it, like a zone with a fixed particle, does not move at all.
struct ImpactZone {
  std::vector<int> particles;  ///< sorted, distinct
  bool half_plane = false;
  bool operator==(const ImpactZone&) const = default;
};

/// The zone of one collision: {i, j}; {i, a, b} for an edge; {i} flagged for a half-plane.
ImpactZone impact_zone_of(const SceneModel& model, const CandidatePair& pair);

/// Merges zones that share a particle (union of particles, flags or'ed) until they are
/// disjoint; the result is sorted by first particle, so equal sets of zones compare equal.
std::vector<ImpactZone> merge_impact_zones(std::vector<ImpactZone> zones);

/// Moves a zone as a rigid body over the step (2D): if it is flagged or holds a fixed particle,
/// each of its particles goes back to its start position xs with velocity 0. Otherwise, with
/// mass-weighted sums over the zone, x_cm = Σ m xs/Σ m, d_cm = Σ m (q - xs)/Σ m,
/// L = Σ m (xs - x_cm) × ((q - xs) - d_cm), I = Σ m ‖xs - x_cm‖², ω = L/I, each particle moves
/// to x = x_cm + d_cm + cos ω (xs - x_cm) + sin ω (xs - x_cm)⊥ with velocity (x - xs)/h.
/// Restitution plays no part.
void apply_rigid_failsafe(const SceneModel& model, const ImpactZone& zone, const Vector& xs,
                          double h, Vector& q, Vector& v);

}  // namespace fosssim
