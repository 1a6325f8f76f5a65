#include "core/collisions/swept_detection.h"

#include "core/collisions/course_swept.h"
#include "core/collisions/intervals.h"

namespace fosssim {

namespace {

/// Particle i's start position and displacement over the step.
template <int D>
struct Motion {
  Vec<D> start, move;
};

template <int D>
Motion<D> motion(const Vector& xs, const Vector& xe, int p) {
  const Vec<D> s = particle_vec<D>(xs, p);
  return {s, particle_vec<D>(xe, p) - s};
}

template <int D>
std::vector<Polynomial> particle_particle(const Motion<D>& m1, const Motion<D>& m2, double R) {
  const Vec<D> p = m2.start - m1.start;
  const Vec<D> w = m2.move - m1.move;
  return {Polynomial({-w.dot(w), -2.0 * p.dot(w), R * R - p.dot(p)}),
          Polynomial({-w.dot(w), -p.dot(w)})};
}

template <int D>
std::vector<Polynomial> particle_half_plane(const Motion<D>& m, const HalfPlane& plane, double R) {
  const Vec<D> P = plane.point.head<D>();
  const Vec<D> N = plane.normal.head<D>();
  const double s = m.move.dot(N);
  const double q = (P - m.start).dot(N);
  return {Polynomial({-s * s, 2.0 * q * s, R * R * N.dot(N) - q * q}), Polynomial({-s * s, q * s})};
}

/// 1 = the particle, 2 and 3 = the edge's ends.
template <int D>
std::vector<Polynomial> particle_edge(const Motion<D>& m1, const Motion<D>& m2, const Motion<D>& m3,
                                      double R) {
  const Vec<D> u = m1.start - m2.start;
  const Vec<D> du = m1.move - m2.move;
  const Vec<D> g0 = m3.start - m2.start;
  const Vec<D> dg = m3.move - m2.move;
  const double a = u.dot(g0);
  const double b = u.dot(dg) + du.dot(g0);
  const double c = du.dot(dg);
  const double d = u.dot(u);
  const double e = du.dot(u);  // ε
  const double f = du.dot(du);
  const double g = g0.dot(g0);
  const double h = dg.dot(g0);
  const double i = dg.dot(dg);
  const double R2 = R * R;
  std::vector<Polynomial> out;
  // Overlap with the edge's line, times ‖g(t)‖².
  out.emplace_back(std::vector<double>{c * c - f * i, 2.0 * b * c - 2.0 * e * i - 2.0 * f * h,
                                       2.0 * a * c + b * b - d * i - f * g - 4.0 * e * h + R2 * i,
                                       2.0 * a * b - 2.0 * d * h - 2.0 * e * g + 2.0 * R2 * h,
                                       a * a - d * g + R2 * g});
  // α(t) > 0.
  out.emplace_back(std::vector<double>{c, b, a});
  // α(t) < 1, measured from the other end.
  const Vec<D> u1 = m1.start - m3.start;
  const Vec<D> du1 = m1.move - m3.move;
  const Vec<D> g1 = m2.start - m3.start;
  const Vec<D> dg1 = m2.move - m3.move;
  out.emplace_back(std::vector<double>{du1.dot(dg1), du1.dot(g1) + u1.dot(dg1), u1.dot(g1)});
  // Approach: the course's expansion of ‖g(t)‖⁴ (Δx_1 - Δx_2 - α(t) dg)·n(t).
  const double A = g, B = h, C = i, Dd = f, E = e, F = a, G = b, H = c;
  const double I = -G, J = -H;
  const double K = A * F;
  const double L = A * G + 2.0 * B * F;
  const double M = A * H + 2.0 * B * G + C * F;
  const double Nq = C * G + 2.0 * B * H;
  const double O = C * H;
  const double P = B, Q = C;
  out.emplace_back(std::vector<double>{
      -H * H * Q - C * C * Dd - 2.0 * O * J,
      -H * H * P - 2.0 * G * H * Q - 4.0 * B * C * Dd - C * C * E - O * I - 2.0 * Nq * J,
      // Course-compatible: -2FGQ here, where the exact expansion has -2FHQ.
      -2.0 * G * H * P - 2.0 * F * G * Q - G * G * Q - 2.0 * A * C * Dd - 4.0 * B * B * Dd -
          4.0 * B * C * E - Nq * I - 2.0 * M * J,
      -2.0 * F * H * P - G * G * P - 2.0 * F * G * Q - 4.0 * A * B * Dd - 2.0 * A * C * E -
          4.0 * B * B * E - M * I - 2.0 * L * J,
      -2.0 * F * G * P - F * F * Q - A * A * Dd - 4.0 * A * B * E - L * I - 2.0 * K * J,
      -F * F * P - A * A * E - K * I});
  return out;
}

}  // namespace

template <int D>
std::vector<Polynomial> swept_polynomials(const SceneModel& model, const CandidatePair& pair,
                                          const Vector& xs, const Vector& xe) {
  const Motion<D> m1 = motion<D>(xs, xe, pair.particle);
  const double r = model.particle_radius[pair.particle];
  switch (pair.kind) {
    case CollisionKind::kParticleParticle:
      return particle_particle<D>(m1, motion<D>(xs, xe, pair.other),
                                  r + model.particle_radius[pair.other]);
    case CollisionKind::kParticleEdge: {
      const Edge& edge = model.edges[pair.other];
      return particle_edge<D>(m1, motion<D>(xs, xe, edge.i), motion<D>(xs, xe, edge.j),
                              r + model.edge_radius[pair.other]);
    }
    case CollisionKind::kParticleSphere: {  // as a particle that never moves
      const Sphere& sphere = model.spheres[pair.other];
      return particle_particle<D>(m1, Motion<D>{sphere.center.head<D>(), Vec<D>::Zero()},
                                  r + sphere.radius);
    }
    case CollisionKind::kParticleHalfPlane:
      break;
  }
  return particle_half_plane<D>(m1, model.half_planes[pair.other], r);
}

template <int D>
std::optional<SweptCollision<D>> detect_swept(const SceneModel& model, const CandidatePair& pair,
                                              const Vector& xs, const Vector& xe,
                                              std::vector<Polynomial>* log) {
  std::vector<Polynomial> polynomials = swept_polynomials<D>(model, pair, xs, xe);
  const double t = first_time(all_positive_intervals(polynomials));
  if (log != nullptr) {
    for (Polynomial& p : polynomials) log->push_back(std::move(p));
  }
  if (!(t <= 1.0)) return std::nullopt;
  SweptCollision<D> hit;
  hit.time = t;
  if constexpr (D == 2) {
    // The course's arithmetic (an edge whose time-t normal is exactly zero is no collision).
    const auto separation = course_swept_separation(model, pair, xs, xe, t);
    if (!separation) return std::nullopt;
    hit.separation = *separation;
  } else {
    hit.separation = separation_of<D>(model, pair, [&](int p) -> Vec<D> {
      const Vec<D> s = particle_vec<D>(xs, p);
      return s + t * (particle_vec<D>(xe, p) - s);
    });
  }
  return hit;
}

template std::vector<Polynomial> swept_polynomials<2>(const SceneModel&, const CandidatePair&,
                                                      const Vector&, const Vector&);
template std::vector<Polynomial> swept_polynomials<3>(const SceneModel&, const CandidatePair&,
                                                      const Vector&, const Vector&);
template std::optional<SweptCollision<2>> detect_swept<2>(const SceneModel&, const CandidatePair&,
                                                          const Vector&, const Vector&,
                                                          std::vector<Polynomial>*);
template std::optional<SweptCollision<3>> detect_swept<3>(const SceneModel&, const CandidatePair&,
                                                          const Vector&, const Vector&,
                                                          std::vector<Polynomial>*);

}  // namespace fosssim
