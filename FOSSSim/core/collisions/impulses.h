#pragma once
// Velocity changes of a collision response with a coefficient of restitution (course-compatible
// formulas, docs/collisions.md).

#include <array>
#include <limits>

#include "core/collisions/candidate_pairs.h"
#include "core/scene_model.h"
#include "core/types.h"

namespace fosssim {

/// The velocity changes of one collision, for the (at most three) particles it involves.
/// Fixed particles get no entry.
template <int D>
struct Impulse {
  int count = 0;
  std::array<int, 3> particle{};
  std::array<Vec<D>, 3> dv;

  void add(int p, const Vec<D>& change) {
    particle[count] = p;
    dv[count] = change;
    ++count;
  }
};

/// The mass a particle has inside impulse formulas: +∞ when it is fixed, so that M/∞ = 0.
inline double impulse_mass(const SceneModel& model, int p) {
  return model.fixed[p] ? std::numeric_limits<double>::infinity() : model.mass[model.dim * p];
}

/// The response to a collision of `pair` along n (the unnormalised shortest vector, from the
/// particle to the other object), computed from the velocities w_of(p) -> Vec<D> with the
/// restitution factor c = (1 + cor)/2 and n̂ = n/‖n‖:
///   particle-particle, s = 2 (w_2 - w_1)·n̂:
///     Δv_1 = c s/(1 + M_1/M_2) n̂,  Δv_2 = -c s/(M_2/M_1 + 1) n̂;
///   particle-edge (1 = particle, 2, 3 = the edge's ends), w_e = (1-α) w_2 + α w_3,
///   s = 2 (w_e - w_1)·n̂:
///     Δv_1 = c s/(1 + (1-α)² M_1/M_2 + α² M_1/M_3) n̂,
///     Δv_2 = -c (1-α) s/(M_2/M_1 + (1-α)² + α² M_2/M_3) n̂,
///     Δv_3 = -c α s/(M_3/M_1 + (1-α)² M_3/M_2 + α²) n̂;
///   particle-half-plane and particle-sphere (an object at rest):  Δv = -c 2 (w·n̂) n̂.
/// M is +∞ for fixed particles, which get no change. The divisions are written exactly in
/// these forms (course-compatible): a fixed particle against an edge with one fixed end and
/// alpha 0 or 1 gives 0/0, a NaN, on the free end, as in the course.
template <int D, typename VelocityOf>
Impulse<D> compute_impulse(const SceneModel& model, const CandidatePair& pair, const Vec<D>& n,
                           double alpha, const VelocityOf& w_of, double cor) {
  const double c = (1.0 + cor) / 2.0;
  const Vec<D> nhat = n / n.norm();
  const int p1 = pair.particle;
  const double M1 = impulse_mass(model, p1);
  const Vec<D> w1 = w_of(p1);
  Impulse<D> impulse;
  switch (pair.kind) {
    case CollisionKind::kParticleParticle: {
      const int p2 = pair.other;
      const double M2 = impulse_mass(model, p2);
      const double s = 2.0 * (w_of(p2) - w1).dot(nhat);
      if (!model.fixed[p1]) impulse.add(p1, c * s / (1.0 + M1 / M2) * nhat);
      if (!model.fixed[p2]) impulse.add(p2, -(c * s / (M2 / M1 + 1.0)) * nhat);
      break;
    }
    case CollisionKind::kParticleEdge: {
      const Edge& edge = model.edges[pair.other];
      const int p2 = edge.i, p3 = edge.j;
      const double M2 = impulse_mass(model, p2), M3 = impulse_mass(model, p3);
      const double a = alpha, b = 1.0 - alpha;
      const Vec<D> we = b * w_of(p2) + a * w_of(p3);
      const double s = 2.0 * (we - w1).dot(nhat);
      if (!model.fixed[p1]) {
        impulse.add(p1, c * s / (1.0 + b * b * M1 / M2 + a * a * M1 / M3) * nhat);
      }
      if (!model.fixed[p2]) {
        impulse.add(p2, -(c * b * s / (M2 / M1 + b * b + a * a * M2 / M3)) * nhat);
      }
      if (!model.fixed[p3]) {
        impulse.add(p3, -(c * a * s / (M3 / M1 + b * b * M3 / M2 + a * a)) * nhat);
      }
      break;
    }
    case CollisionKind::kParticleHalfPlane:
    case CollisionKind::kParticleSphere:
      if (!model.fixed[p1]) impulse.add(p1, -(c * 2.0 * w1.dot(nhat)) * nhat);
      break;
  }
  return impulse;
}

}  // namespace fosssim
