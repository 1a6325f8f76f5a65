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
/// Fixed particles get no entry (but for the course's 2D half-planes, compute_impulse).
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
/// coefficient of restitution cor, n̂ = n × (1/‖n‖) and S = s (1 + cor), in the course's order
/// of operations (docs/collisions.md, 'Course-exact arithmetic'):
///   particle-particle, s = (w_2 - w_1)·n̂:
///     Δv_1 = n̂ (S ÷ ((M_1 ÷ M_2) + 1)),  Δv_2 = -n̂ (S ÷ ((M_2 ÷ M_1) + 1));
///   particle-edge (1 = particle, 2, 3 = the edge's ends), β = 1 - α,
///   w_e = (w_3 - w_2) α + w_2, s = (w_e - w_1)·n̂:
///     Δv_1 = n̂ (S ÷ ((((β² M_1) ÷ M_2) + 1) + ((M_1 α²) ÷ M_3))),
///     Δv_2 = -n̂ ((β S) ÷ (((M_2 ÷ M_1) + β²) + ((M_2 α²) ÷ M_3))),
///     Δv_3 = -n̂ ((S α) ÷ (((M_3 ÷ M_1) + ((M_3 β²) ÷ M_2)) + α²));
///   particle-half-plane and particle-sphere (an object at rest), s = w·n̂:  Δv = -n̂ S.
/// M is +∞ for fixed particles, which get no change, except against a 2D half-plane: the course
/// bounces a fixed particle off a half-plane too (it then moves with its new velocity). The
/// divisions are written exactly in these forms: a fixed particle against an edge with one fixed
/// end and alpha 0 or 1 gives 0/0, a NaN, on the free end, as in the course.
template <int D, typename VelocityOf>
Impulse<D> compute_impulse(const SceneModel& model, const CandidatePair& pair, const Vec<D>& n,
                           double alpha, const VelocityOf& w_of, double cor) {
  const double restitution = 1.0 + cor;
  const double reciprocal = 1.0 / n.norm();
  const Vec<D> nhat = n * reciprocal;
  const int p1 = pair.particle;
  const double M1 = impulse_mass(model, p1);
  const Vec<D> w1 = w_of(p1);
  Impulse<D> impulse;
  switch (pair.kind) {
    case CollisionKind::kParticleParticle: {
      const int p2 = pair.other;
      const double M2 = impulse_mass(model, p2);
      const double S = (w_of(p2) - w1).dot(nhat) * restitution;
      if (!model.fixed[p1]) impulse.add(p1, nhat * (S / ((M1 / M2) + 1.0)));
      if (!model.fixed[p2]) impulse.add(p2, -(nhat * (S / ((M2 / M1) + 1.0))));
      break;
    }
    case CollisionKind::kParticleEdge: {
      const Edge& edge = model.edges[pair.other];
      const int p2 = edge.i, p3 = edge.j;
      const double M2 = impulse_mass(model, p2), M3 = impulse_mass(model, p3);
      const double a = alpha, b = 1.0 - alpha;
      const double a2 = a * a, b2 = b * b;
      const Vec<D> w2 = w_of(p2);
      const Vec<D> we = (w_of(p3) - w2) * a + w2;
      const double S = (we - w1).dot(nhat) * restitution;
      if (!model.fixed[p1]) {
        impulse.add(p1, nhat * (S / ((((b2 * M1) / M2) + 1.0) + ((M1 * a2) / M3))));
      }
      if (!model.fixed[p2]) {
        impulse.add(p2, -(nhat * ((b * S) / (((M2 / M1) + b2) + ((M2 * a2) / M3)))));
      }
      if (!model.fixed[p3]) {
        impulse.add(p3, -(nhat * ((S * a) / (((M3 / M1) + ((M3 * b2) / M2)) + a2))));
      }
      break;
    }
    case CollisionKind::kParticleHalfPlane:
    case CollisionKind::kParticleSphere: {
      const bool bounces_fixed = D == 2 && pair.kind == CollisionKind::kParticleHalfPlane;
      if (!model.fixed[p1] || bounces_fixed) {
        impulse.add(p1, -(nhat * (w1.dot(nhat) * restitution)));
      }
      break;
    }
  }
  return impulse;
}

}  // namespace fosssim
