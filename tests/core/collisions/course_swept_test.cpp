// Continuous-time handling in 2D follows the course's arithmetic (docs/collisions.md,
// "Continuous time in the course's arithmetic"): the normal at the collision time and the
// response are checked bit for bit against the course's expressions written out here in its
// order, on steps where FOSSSim's former formulas (the discrete separation at xs + tΔx, the
// impulses of impulses.h from (X - xs)/h, X += hΔv) give other bits, so that going back to
// them fails.

#include "core/collisions/course_swept.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/collisions/impulses.h"
#include "core/step/step_pipeline.h"
#include "support/random.h"
#include "support/scene_builder.h"

namespace fosssim {
// Named, so that a unity build of the tests meets no clash of helper names.
namespace course_swept_test {

using testing::Random;
using testing::TestScene;
using testing::vec;

using D2 = std::array<double, 2>;

enum class Kind { kParticles, kEdge, kHalfPlane };

double dot2(const D2& a, const D2& b) { return a[0] * b[0] + a[1] * b[1]; }

/// The end of one step of `scene` under contact method `method`, and what it recorded.
struct StepResult {
  State end;
  StepRecord record;
};

TestScene one_collision_scene(Kind kind, unsigned seed);

/// One step of one_collision_scene(kind, seed) under contact method `method`.
StepResult step_with(Kind kind, unsigned seed, const char* method) {
  TestScene scene = one_collision_scene(kind, seed);
  scene.model.collisions.method = &contact_method(method);
  StepPipeline pipeline(scene.model);
  StepResult result;
  result.end = scene.initial;
  pipeline.step(result.end, &result.record);
  return result;
}

/// The course's normal and response (SPEC order, written out independently of the library),
/// and FOSSSim's former ones, for the single collision of a step.
struct Outcome {
  D2 normal{};
  Vector X, V;
};

/// A step with exactly one collision: particle 0 against particle 1, against edge (1, 2), or
/// against half-plane 0; masses, COR and geometry drawn from `seed`; no forces, explicit Euler.
TestScene one_collision_scene(Kind kind, unsigned seed) {
  Random random(seed);
  TestScene scene(2, "explicit-euler", 0.1);
  scene.model.collisions.cor = random.uniform(0.0, 1.0);
  const auto r = [&random](double lo, double hi) { return random.uniform(lo, hi); };
  switch (kind) {
    case Kind::kParticles:
      scene.add_particle(r(0.5, 3), vec({r(-0.65, -0.55), r(-0.05, 0.05)}),
                         vec({r(7, 9), r(-0.5, 0.5)}), false, 0.1);
      scene.add_particle(r(0.5, 3), vec({r(-0.05, 0.05), r(-0.05, 0.05)}),
                         vec({r(-1, 1), r(-0.5, 0.5)}), false, 0.1);
      break;
    case Kind::kEdge:
      scene.add_particle(r(0.5, 3), vec({r(-0.1, 0.1), r(0.45, 0.55)}),
                         vec({r(-0.5, 0.5), r(-9, -7)}), false, 0.05);
      scene.add_particle(r(0.5, 3), vec({r(-0.55, -0.45), r(-0.05, 0.05)}),
                         vec({r(-0.5, 0.5), r(-0.5, 0.5)}), false, 0.05);
      scene.add_particle(r(0.5, 3), vec({r(0.45, 0.55), r(-0.05, 0.05)}),
                         vec({r(-0.5, 0.5), r(-0.5, 0.5)}), false, 0.05);
      scene.add_edge(1, 2, 0.015);
      break;
    case Kind::kHalfPlane:
      scene.add_particle(r(0.5, 3), vec({r(-0.1, 0.1), r(0.45, 0.55)}),
                         vec({r(-2, 2), r(-9, -7)}), false, 0.1);
      scene.add_half_plane(vec({r(-0.1, 0.1), r(-0.1, 0.1)}), vec({r(-0.4, 0.4), r(0.7, 1.3)}));
      break;
  }
  return scene;
}

double mass_of(const SceneModel& model, int p) { return impulse_mass(model, p); }

/// The course's time-t normal and response, from the start xs, the integrated end X, V and t.
Outcome course_outcome(const SceneModel& model, Kind kind, const Vector& xs, Vector X, Vector V,
                       double t, double h, double cor) {
  const auto dx = [&](int p, int k) { return X[2 * p + k] - xs[2 * p + k]; };
  const auto y = [&](int p, int k) { return dx(p, k) * t + xs[2 * p + k]; };
  Outcome out;
  D2 n{};
  double alpha = 0.0;
  switch (kind) {
    case Kind::kParticles:
      n = {y(1, 0) - y(0, 0), y(1, 1) - y(0, 1)};
      break;
    case Kind::kEdge: {
      D2 E, W, un, w;
      for (int k = 0; k < 2; ++k) {
        E[k] = ((dx(2, k) * t + xs[4 + k]) - xs[2 + k]) - dx(1, k) * t;
        W[k] = ((dx(0, k) * t + xs[k]) - xs[2 + k]) - dx(1, k) * t;
      }
      const double a = dot2(W, E) / dot2(E, E);
      for (int k = 0; k < 2; ++k) n[k] = (((E[k] * a) + (dx(1, k) * t + xs[2 + k])) - xs[k]) - dx(0, k) * t;
      for (int k = 0; k < 2; ++k) {
        un[k] = y(2, k) - y(1, k);
        w[k] = y(0, k) - y(1, k);
      }
      alpha = dot2(w, un) / dot2(un, un);
      alpha = alpha > 0.0 ? std::min(alpha, 1.0) : 0.0;
      break;
    }
    case Kind::kHalfPlane: {
      const HalfPlane& plane = model.half_planes[0];
      const D2 N{plane.normal[0], plane.normal[1]};
      D2 d;
      for (int k = 0; k < 2; ++k) d[k] = (plane.point[k] - xs[k]) - dx(0, k) * t;
      const double tau = dot2(d, N) / dot2(N, N);
      n = {N[0] * tau, tau * N[1]};
      break;
    }
  }
  out.normal = n;
  const double rh = 1.0 / h;
  const auto vt = [&](int p) -> D2 {
    return {(X[2 * p] - xs[2 * p]) * rh, (X[2 * p + 1] - xs[2 * p + 1]) * rh};
  };
  const double l = std::sqrt(dot2(n, n));
  const double inv = 1.0 / l;
  const D2 nh{n[0] * inv, n[1] * inv};
  const double c = (1.0 + cor) * 0.5;
  const auto add = [&](Vector& x, int p, double a) {  // x_p = n̂×a + x_p
    for (int k = 0; k < 2; ++k) x[2 * p + k] = nh[k] * a + x[2 * p + k];
  };
  const auto sub = [&](Vector& x, int p, double a) {  // x_p = x_p - n̂×a
    for (int k = 0; k < 2; ++k) x[2 * p + k] = x[2 * p + k] - nh[k] * a;
  };
  const D2 v0 = vt(0);
  const double M0 = mass_of(model, 0);
  switch (kind) {
    case Kind::kParticles: {
      const D2 v1 = vt(1);
      const double M1 = mass_of(model, 1);
      const double S = dot2(D2{v1[0] - v0[0], v1[1] - v0[1]}, nh) * (c + c);
      const double D0 = (M0 / M1) + 1.0, D1 = (M1 / M0) + 1.0;
      add(V, 0, S / D0);
      add(X, 0, (h * S) / D0);
      sub(V, 1, S / D1);
      sub(X, 1, (h * S) / D1);
      break;
    }
    case Kind::kEdge: {
      const D2 va = vt(1), vb = vt(2);
      const double Ma = mass_of(model, 1), Mb = mass_of(model, 2);
      const D2 ve{(vb[0] - va[0]) * alpha + va[0], (vb[1] - va[1]) * alpha + va[1]};
      const double S = dot2(D2{ve[0] - v0[0], ve[1] - v0[1]}, nh) * (c + c);
      const double b = 1.0 - alpha, b2 = b * b, a2 = alpha * alpha;
      const double Di = (((b2 * M0) / Ma) + 1.0) + ((M0 * a2) / Mb);
      const double Da = ((Ma / M0) + b2) + ((Ma * a2) / Mb);
      const double Db = ((Mb / M0) + ((Mb * b2) / Ma)) + a2;
      add(V, 0, S / Di);
      add(X, 0, (h * S) / Di);
      sub(V, 1, (b * S) / Da);
      sub(X, 1, ((h * b) * S) / Da);
      sub(V, 2, (S * alpha) / Db);
      sub(X, 2, ((h * alpha) * S) / Db);
      break;
    }
    case Kind::kHalfPlane: {
      const double s = dot2(v0, nh);
      sub(V, 0, s * (c + c));
      sub(X, 0, ((h + h) * c) * s);
      break;
    }
  }
  out.X = std::move(X);
  out.V = std::move(V);
  return out;
}

/// FOSSSim's former continuous-time arithmetic: the discrete separation at xs + t(X - xs), the
/// impulses of impulses.h from (X - xs)/h, V += Δv and X += hΔv.
Outcome former_outcome(const SceneModel& model, const CandidatePair& pair, const Vector& xs,
                       Vector X, Vector V, double t, double h, double cor) {
  const Separation<2> s = separation_of<2>(model, pair, [&](int p) -> Vec<2> {
    const Vec<2> start = particle_vec<2>(xs, p);
    return start + t * (particle_vec<2>(X, p) - start);
  });
  const auto w = [&](int p) -> Vec<2> {
    return (particle_vec<2>(X, p) - particle_vec<2>(xs, p)) / h;
  };
  const Impulse<2> impulse = compute_impulse<2>(model, pair, s.n, s.alpha, w, cor);
  for (int k = 0; k < impulse.count; ++k) {
    V.segment<2>(2 * impulse.particle[k]) += impulse.dv[k];
    X.segment<2>(2 * impulse.particle[k]) += h * impulse.dv[k];
  }
  return {{s.n[0], s.n[1]}, std::move(X), std::move(V)};
}

CandidatePair pair_of(Kind kind) {
  switch (kind) {
    case Kind::kParticles:
      return {CollisionKind::kParticleParticle, 0, 1};
    case Kind::kEdge:
      return {CollisionKind::kParticleEdge, 0, 0};
    case Kind::kHalfPlane:
      break;
  }
  return {CollisionKind::kParticleHalfPlane, 0, 0};
}

/// Over `seeds` drawn scenes of `kind`: the stage's record and end state are the course's
/// expressions bit for bit every time; returns how many seeds the former arithmetic gave other
/// normals and other end states for.
std::array<int, 2> check_course_arithmetic(Kind kind, unsigned seeds) {
  std::array<int, 2> former_differs{0, 0};
  for (unsigned seed = 1; seed <= seeds; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    const TestScene scene = one_collision_scene(kind, seed);
    const StepResult free = step_with(kind, seed, "none");  // the integrator's X and V
    const StepResult hit = step_with(kind, seed, "continuous-time");
    EXPECT_TRUE(free.record.collisions.empty());
    if (hit.record.collisions.size() != 1u) {
      ADD_FAILURE() << "expected one collision, found " << hit.record.collisions.size();
      continue;
    }
    const CollisionRecord& record = hit.record.collisions[0];
    const double t = record.time;
    const double h = scene.model.integrator.dt;
    const double cor = scene.model.collisions.cor;
    const Vector& xs = scene.initial.q;
    const Outcome course =
        course_outcome(scene.model, kind, xs, free.end.q, free.end.v, t, h, cor);
    EXPECT_EQ(record.normal[0], course.normal[0]);
    EXPECT_EQ(record.normal[1], course.normal[1]);
    EXPECT_EQ(hit.end.q, course.X);
    EXPECT_EQ(hit.end.v, course.V);
    const Outcome former =
        former_outcome(scene.model, pair_of(kind), xs, free.end.q, free.end.v, t, h, cor);
    if (former.normal != course.normal) ++former_differs[0];
    if (former.X != course.X || former.V != course.V) ++former_differs[1];
  }
  return former_differs;
}

TEST(CourseSwept, ParticleParticleResponseIsTheCoursesBitForBit) {
  const auto former_differs = check_course_arithmetic(Kind::kParticles, 40);
  // The normal y_j - y_i was already the course's; the response was not.
  EXPECT_EQ(former_differs[0], 0);
  EXPECT_GT(former_differs[1], 0);
}

TEST(CourseSwept, ParticleEdgeNormalAndResponseAreTheCoursesBitForBit) {
  const auto former_differs = check_course_arithmetic(Kind::kEdge, 40);
  EXPECT_GT(former_differs[0], 0);
  EXPECT_GT(former_differs[1], 0);
}

TEST(CourseSwept, ParticleHalfPlaneNormalAndResponseAreTheCoursesBitForBit) {
  const auto former_differs = check_course_arithmetic(Kind::kHalfPlane, 40);
  EXPECT_GT(former_differs[0], 0);
  EXPECT_GT(former_differs[1], 0);
}

TEST(CourseSwept, AnEdgeNormalThatIsExactlyZeroIsNoCollision) {
  // A particle on the edge's line at time t: the course's n is exactly zero and it answers
  // nothing, where a normalised zero would put NaNs into the state.
  TestScene scene(2, "explicit-euler", 0.1);
  scene.add_particle(1, vec({0.5, 0}), vec({0, 0}));
  scene.add_particle(1, vec({0, 0}), vec({0, 0}));
  scene.add_particle(1, vec({1, 0}), vec({0, 0}));
  scene.add_edge(1, 2);
  const CandidatePair pair{CollisionKind::kParticleEdge, 0, 0};
  const Vector& x = scene.initial.q;
  EXPECT_FALSE(course_swept_separation(scene.model, pair, x, x, 0.0));
  EXPECT_FALSE(course_swept_separation(scene.model, pair, x, x, 1.0));
  // Off the line the same call gives the separation, unnormalised.
  scene.initial.q[1] = -0.25;
  const auto s = course_swept_separation(scene.model, pair, x, x, 0.5);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->n, vec({0, 0.25}));
  EXPECT_EQ(s->alpha, 0.5);
  EXPECT_EQ(s->distance, 0.25);
}

TEST(CourseSwept, TheEdgeNormalUsesTheUnclampedParameterAndTheResponseTheClampedOne) {
  // The particle beyond the edge's end b: the normal reaches the edge's line (α = 1.5), the
  // response's α is 1.
  TestScene scene(2, "explicit-euler", 0.1);
  scene.add_particle(1, vec({1.5, 0.25}), vec({0, 0}));
  scene.add_particle(1, vec({0, 0}), vec({0, 0}));
  scene.add_particle(1, vec({1, 0}), vec({0, 0}));
  scene.add_edge(1, 2);
  const Vector& x = scene.initial.q;
  const auto s = course_swept_separation(scene.model, {CollisionKind::kParticleEdge, 0, 0}, x, x,
                                         0.0);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->n, vec({0, -0.25}));
  EXPECT_EQ(s->alpha, 1.0);
}

}  // namespace course_swept_test
}  // namespace fosssim
