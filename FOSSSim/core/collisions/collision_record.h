#pragma once
// One collision found in a step, as the trajectory file records it.

#include "core/types.h"

namespace fosssim {

/// What collided with a particle. The values are the type codes of the course's trajectory
/// records (docs/collisions.md); spheres are FOSSSim's own, in 3D only.
enum class CollisionKind : int {
  kParticleParticle = 0,   ///< first < second are particles
  kParticleEdge = 1,       ///< a particle and an edge
  kParticleHalfPlane = 2,  ///< a particle and a half-plane
  kParticleSphere = 3,     ///< a particle and a static sphere (FOSSSim's own)
};

/// True for the objects that never move: half-planes and spheres.
inline bool is_obstacle(CollisionKind kind) {
  return kind == CollisionKind::kParticleHalfPlane || kind == CollisionKind::kParticleSphere;
}

/// A collision as recorded: the pair, the normal and when in the step it happened.
struct CollisionRecord {
  CollisionKind kind = CollisionKind::kParticleParticle;
  int first = 0;   ///< the particle (the lower index for particle-particle)
  int second = 0;  ///< the other particle, the edge or the half-plane
  /// The separation (core/collisions/proximity.h; not normalised), size dim:
  /// at the end of the step (simple) or at the collision time (continuous-time).
  Vector normal;
  double time = 0.0;  ///< fraction of the step in [0, 1]; 0 for discrete detection

  bool same_pair(const CollisionRecord& other) const {
    return kind == other.kind && first == other.first && second == other.second;
  }
};

}  // namespace fosssim
