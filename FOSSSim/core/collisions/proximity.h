#pragma once
// Shortest vectors between a particle and the other objects, and the discrete collision test
// (course-compatible formulas, docs/collisions.md).

#include <algorithm>
#include <cmath>

#include "core/collisions/candidate_pairs.h"
#include "core/scene_model.h"
#include "core/types.h"

namespace fosssim {

/// The shortest vector from a particle to another object, and where on an edge it ends.
template <int D>
struct Separation {
  Vec<D> n;            ///< from the particle to the closest point of the other object
  double alpha = 0.0;  ///< particle-edge: the closest point is x_a + alpha (x_b - x_a)
  double radii = 0.0;  ///< the sum of the radii (the particle's alone for a half-plane)
  /// ‖n‖, except for a half-space in 3D: the signed distance of the particle's centre from its
  /// boundary, negative inside the solid.
  double distance = 0.0;
};

/// clamp(s, 0, 1) written as the course does: min(1, max(0, s)).
inline double clamp01(double s) { return std::min(1.0, std::max(0.0, s)); }

/// The edge parameter of the point of segment [xa, xb] closest to x, clamped to [0, 1].
template <int D>
double closest_edge_parameter(const Vec<D>& x, const Vec<D>& xa, const Vec<D>& xb) {
  const Vec<D> e = xb - xa;
  return clamp01((x - xa).dot(e) / e.squaredNorm());
}

/// n = ((P - x)·N / (N·N)) N: the vector from x to its projection on the half-plane's
/// boundary. Its direction depends on the side x is on (the course's unsigned distance, in 2D;
/// separation_of signs it in 3D).
template <int D>
Vec<D> half_plane_vector(const Vec<D>& x, const HalfPlane& plane) {
  const Vec<D> P = plane.point.head<D>();
  const Vec<D> N = plane.normal.head<D>();
  return ((P - x).dot(N) / N.dot(N)) * N;
}

/// The half-plane vector of the course's simple collisions (2D), with the normal made a unit
/// vector by its reciprocal length: N̂ = N × (1/√(N·N)), n = ((P - x)·N̂) N̂. The same vector as
/// half_plane_vector up to round-off, rounded as the course's detection rounds it (its records
/// hold this n).
template <int D>
Vec<D> unit_half_plane_vector(const Vec<D>& x, const HalfPlane& plane) {
  const Vec<D> N = plane.normal.head<D>();
  const Vec<D> unit = N * (1.0 / std::sqrt(N.dot(N)));
  const double distance = (plane.point.head<D>() - x).dot(unit);
  return unit * distance;
}

/// The separation of `pair` for the positions x_of(p) -> Vec<D>.
template <int D, typename PositionOf>
Separation<D> separation_of(const SceneModel& model, const CandidatePair& pair,
                            const PositionOf& x_of) {
  const int i = pair.particle;
  const Vec<D> x = x_of(i);
  Separation<D> s;
  switch (pair.kind) {
    case CollisionKind::kParticleParticle:
      s.n = x_of(pair.other) - x;
      s.radii = model.particle_radius[i] + model.particle_radius[pair.other];
      break;
    case CollisionKind::kParticleEdge: {
      const Edge& edge = model.edges[pair.other];
      const Vec<D> xa = x_of(edge.i);
      const Vec<D> xb = x_of(edge.j);
      s.alpha = closest_edge_parameter<D>(x, xa, xb);
      s.n = xa + s.alpha * (xb - xa) - x;
      s.radii = model.particle_radius[i] + model.edge_radius[pair.other];
      break;
    }
    case CollisionKind::kParticleHalfPlane:
      s.radii = model.particle_radius[i];
      if constexpr (D == 3) {
        // FOSSSim's own in 3D (the course has no 3D): n always points into the solid and the
        // distance is signed, so a particle whose centre has crossed the boundary is still
        // detected and pushed out. On the free side this is the course's n, bit for bit.
        const HalfPlane& plane = model.half_planes[pair.other];
        const Vec<D> N = plane.normal.head<D>();
        const double side = (x - plane.point.head<D>()).dot(N);
        s.n = -(std::abs(side) / N.dot(N)) * N;
        s.distance = side / N.norm();
        return s;
      }
      s.n = half_plane_vector<D>(x, model.half_planes[pair.other]);
      break;
    case CollisionKind::kParticleSphere: {  // a particle that never moves
      const Sphere& sphere = model.spheres[pair.other];
      s.n = sphere.center.head<D>() - x;
      s.radii = model.particle_radius[i] + sphere.radius;
      break;
    }
  }
  s.distance = s.n.norm();
  return s;
}

/// The separation of `pair` for positions q (size D·n).
template <int D>
Separation<D> separation(const SceneModel& model, const CandidatePair& pair, const Vector& q) {
  return separation_of<D>(model, pair, [&q](int p) -> Vec<D> { return particle_vec<D>(q, p); });
}

/// The separation the course's simple collisions detect with: separation() but for a 2D
/// half-plane, whose vector is unit_half_plane_vector.
template <int D>
Separation<D> simple_separation(const SceneModel& model, const CandidatePair& pair,
                                const Vector& q) {
  Separation<D> s = separation<D>(model, pair, q);
  if constexpr (D == 2) {
    if (pair.kind == CollisionKind::kParticleHalfPlane) {
      s.n = unit_half_plane_vector<D>(particle_vec<D>(q, pair.particle),
                                      model.half_planes[pair.other]);
      s.distance = s.n.norm();
    }
  }
  return s;
}

/// The velocity of the particle relative to the closest point of the other object, (v_i - v_other)
/// with the edge's velocity interpolated at alpha; half-planes and spheres are at rest.
template <int D>
Vec<D> relative_velocity(const SceneModel& model, const CandidatePair& pair, double alpha,
                         const Vector& v) {
  const Vec<D> vi = particle_vec<D>(v, pair.particle);
  switch (pair.kind) {
    case CollisionKind::kParticleParticle:
      return vi - particle_vec<D>(v, pair.other);
    case CollisionKind::kParticleEdge: {
      const Edge& edge = model.edges[pair.other];
      const Vec<D> va = particle_vec<D>(v, edge.i);
      const Vec<D> vb = particle_vec<D>(v, edge.j);
      return vi - va - alpha * (vb - va);
    }
    case CollisionKind::kParticleHalfPlane:
    case CollisionKind::kParticleSphere:
      break;
  }
  return vi;
}

/// The discrete test (course-compatible): the objects overlap, distance < radii, and approach,
/// (relative velocity)·n > 0, both strictly. Touching exactly, or moving tangentially, is not a
/// collision; neither is a particle whose centre lies on an edge or a half-plane's boundary
/// (n = 0).
template <int D>
bool is_colliding(const SceneModel& model, const CandidatePair& pair, const Separation<D>& s,
                  const Vector& v) {
  if (!(s.distance < s.radii)) return false;
  return relative_velocity<D>(model, pair, s.alpha, v).dot(s.n) > 0.0;
}

}  // namespace fosssim
