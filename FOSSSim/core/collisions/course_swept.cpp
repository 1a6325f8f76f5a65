#include "core/collisions/course_swept.h"

#include <algorithm>
#include <cmath>

#include "core/collisions/impulses.h"

// Scalar code on purpose: every line is one rounding in the course's order, which an Eigen
// expression would leave to the library (docs/collisions.md).

namespace fosssim {

// Named, not anonymous: the library is built in unity batches, where short helper names of
// different files would meet.
namespace course_swept_detail {

struct P2 {
  double x = 0.0, y = 0.0;
};

double dot(const P2& a, const P2& b) { return a.x * b.x + a.y * b.y; }

/// Where particle p starts, xs_p, and how far it moves over the step, Δx_p = X_p - xs_p.
struct Swept {
  P2 start, move;

  /// Δx×t (per coordinate).
  P2 moved_by(double t) const { return {move.x * t, move.y * t}; }
  /// y = Δx×t + xs.
  P2 at(double t) const { return {move.x * t + start.x, move.y * t + start.y}; }
};

Swept swept(const Vector& xs, const Vector& X, int p) {
  const double sx = xs[2 * p], sy = xs[2 * p + 1];
  return {{sx, sy}, {X[2 * p] - sx, X[2 * p + 1] - sy}};
}

/// The course's clamp of an edge parameter: α > 0 ? min(α, 1) : 0 (a NaN gives 0).
double course_clamp(double alpha) { return alpha > 0.0 ? std::min(alpha, 1.0) : 0.0; }

P2 get(const Vector& x, int p) { return {x[2 * p], x[2 * p + 1]}; }
void set(Vector& x, int p, const P2& value) {
  x[2 * p] = value.x;
  x[2 * p + 1] = value.y;
}

}  // namespace course_swept_detail

std::optional<Separation<2>> course_swept_separation(const SceneModel& model,
                                                     const CandidatePair& pair, const Vector& xs,
                                                     const Vector& X, double t) {
  using namespace course_swept_detail;
  const int i = pair.particle;
  const Swept si = swept(xs, X, i);
  Separation<2> s;
  P2 n;
  switch (pair.kind) {
    case CollisionKind::kParticleParticle: {
      const P2 yi = si.at(t), yj = swept(xs, X, pair.other).at(t);
      n = {yj.x - yi.x, yj.y - yi.y};
      s.radii = model.particle_radius[i] + model.particle_radius[pair.other];
      break;
    }
    case CollisionKind::kParticleEdge: {
      const Edge& edge = model.edges[pair.other];
      const Swept sa = swept(xs, X, edge.i), sb = swept(xs, X, edge.j);
      const P2 da = sa.moved_by(t), di = si.moved_by(t);
      const P2 yb = sb.at(t), yi = si.at(t), ya = sa.at(t);
      const P2 E{(yb.x - sa.start.x) - da.x, (yb.y - sa.start.y) - da.y};
      const P2 W{(yi.x - sa.start.x) - da.x, (yi.y - sa.start.y) - da.y};
      const double alpha = dot(W, E) / dot(E, E);  // not clamped
      n = {((E.x * alpha + ya.x) - si.start.x) - di.x, ((E.y * alpha + ya.y) - si.start.y) - di.y};
      if (n.x == 0.0 && n.y == 0.0) return std::nullopt;
      // The response's α: from the positions at time t, clamped.
      const P2 u{yb.x - ya.x, yb.y - ya.y};
      const P2 w{yi.x - ya.x, yi.y - ya.y};
      s.alpha = course_clamp(dot(w, u) / dot(u, u));
      s.radii = model.particle_radius[i] + model.edge_radius[pair.other];
      break;
    }
    case CollisionKind::kParticleHalfPlane: {
      const HalfPlane& plane = model.half_planes[pair.other];
      const P2 P{plane.point[0], plane.point[1]};
      const P2 N{plane.normal[0], plane.normal[1]};
      const P2 di = si.moved_by(t);
      const P2 to_plane{(P.x - si.start.x) - di.x, (P.y - si.start.y) - di.y};
      const double tau = dot(to_plane, N) / dot(N, N);
      n = {N.x * tau, tau * N.y};
      s.radii = model.particle_radius[i];
      break;
    }
    case CollisionKind::kParticleSphere:  // 3D only: never reaches the 2D path
      return std::nullopt;
  }
  s.n = Vec<2>(n.x, n.y);
  s.distance = std::sqrt(dot(n, n));
  return s;
}

MovedParticles respond_course_swept(const SceneModel& model, const CandidatePair& pair,
                                    const Separation<2>& separation, const Vector& xs, double h,
                                    double cor, State& state) {
  using namespace course_swept_detail;
  Vector& X = state.q;
  Vector& V = state.v;
  const double inverse_h = 1.0 / h;
  // ṽ_p = (X_p - xs_p)×(1/h), from the positions as this response finds them.
  const auto v_tilde = [&](int p) -> P2 {
    return {(X[2 * p] - xs[2 * p]) * inverse_h, (X[2 * p + 1] - xs[2 * p + 1]) * inverse_h};
  };
  const P2 n{separation.n[0], separation.n[1]};
  const double reciprocal = 1.0 / std::sqrt(dot(n, n));
  const P2 nhat{n.x * reciprocal, n.y * reciprocal};
  const double c = (1.0 + cor) * 0.5;
  // p += n̂×a (sign +1) or p -= n̂×a (sign -1), the course writing both as shown.
  const auto push = [&](Vector& x, int p, double a, bool plus) {
    const P2 old = get(x, p);
    const P2 d{nhat.x * a, nhat.y * a};
    set(x, p, plus ? P2{d.x + old.x, d.y + old.y} : P2{old.x - d.x, old.y - d.y});
  };
  const int i = pair.particle;
  const double Mi = impulse_mass(model, i);
  const P2 vi = v_tilde(i);
  MovedParticles moved;
  const auto note = [&moved](int p) { moved.particle[moved.count++] = p; };
  switch (pair.kind) {
    case CollisionKind::kParticleParticle: {
      const int j = pair.other;
      const double Mj = impulse_mass(model, j);
      const P2 vj = v_tilde(j);
      const double s = dot(P2{vj.x - vi.x, vj.y - vi.y}, nhat);
      const double S = s * (c + c);
      if (!model.fixed[i]) {
        const double Di = (Mi / Mj) + 1.0;
        push(V, i, S / Di, true);
        push(X, i, (h * S) / Di, true);
        note(i);
      }
      if (!model.fixed[j]) {
        const double Dj = (Mj / Mi) + 1.0;
        push(V, j, S / Dj, false);
        push(X, j, (h * S) / Dj, false);
        note(j);
      }
      break;
    }
    case CollisionKind::kParticleEdge: {
      const Edge& edge = model.edges[pair.other];
      const int a = edge.i, b = edge.j;
      const double Ma = impulse_mass(model, a), Mb = impulse_mass(model, b);
      const P2 va = v_tilde(a), vb = v_tilde(b);
      const double alpha = separation.alpha;
      const P2 ve{(vb.x - va.x) * alpha + va.x, (vb.y - va.y) * alpha + va.y};
      const double s = dot(P2{ve.x - vi.x, ve.y - vi.y}, nhat);
      const double S = s * (c + c);
      const double beta = 1.0 - alpha;
      const double beta2 = beta * beta, alpha2 = alpha * alpha;
      if (!model.fixed[i]) {
        const double Di = ((((beta2 * Mi) / Ma) + 1.0) + ((Mi * alpha2) / Mb));
        push(V, i, S / Di, true);
        push(X, i, (h * S) / Di, true);
        note(i);
      }
      if (!model.fixed[a]) {
        const double Da = (((Ma / Mi) + beta2) + ((Ma * alpha2) / Mb));
        push(V, a, (beta * S) / Da, false);
        push(X, a, ((h * beta) * S) / Da, false);
        note(a);
      }
      if (!model.fixed[b]) {
        const double Db = (((Mb / Mi) + ((Mb * beta2) / Ma)) + alpha2);
        push(V, b, (S * alpha) / Db, false);
        push(X, b, ((h * alpha) * S) / Db, false);
        note(b);
      }
      break;
    }
    case CollisionKind::kParticleHalfPlane: {  // fixed particles bounce too (the course's rule)
      const double s = dot(vi, nhat);
      push(V, i, s * (c + c), false);
      push(X, i, ((h + h) * c) * s, false);
      note(i);
      break;
    }
    case CollisionKind::kParticleSphere:  // 3D only
      break;
  }
  return moved;
}

}  // namespace fosssim
