// Continuous-time detection: polynomials against direct evaluation along the step, the
// interval logic, and the course's worked examples of continuous-time and hybrid handling.

#include "core/collisions/swept_detection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/collisions/impact_zones.h"
#include "core/collisions/intervals.h"
#include "core/step/step_pipeline.h"
#include "support/closed_forms.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

using testing::Random;
using testing::TestScene;
using testing::vec;

constexpr double kInf = std::numeric_limits<double>::infinity();

template <int D>
Vec<D> at(const Vector& xs, const Vector& xe, int p, double t) {
  const Vec<D> s = particle_vec<D>(xs, p);
  return s + t * (particle_vec<D>(xe, p) - s);
}

template <int D>
void expect_polynomials_match_direct_evaluation(unsigned seed) {
  Random random(seed);
  TestScene scene(D);
  for (int p = 0; p < 3; ++p) {
    scene.add_particle(1, random.uniform_vector(D, -1, 1), Vector::Zero(D), false,
                       random.uniform(0.1, 0.5));
  }
  scene.add_edge(1, 2, 0.2);
  scene.add_half_plane(random.uniform_vector(D, -1, 1), random.uniform_vector(D, -2, 2));
  const SceneModel& model = scene.model;
  const Vector xs = scene.initial.q;
  const Vector xe = xs + random.uniform_vector(3 * D, -0.5, 0.5);
  const double r0 = model.particle_radius[0];
  for (double t : {0.0, 0.3, 0.77, 1.0, -0.4, 1.6}) {
    const Vec<D> x0 = at<D>(xs, xe, 0, t), x1 = at<D>(xs, xe, 1, t), x2 = at<D>(xs, xe, 2, t);
    const Vec<D> d0 = particle_vec<D>(xe, 0) - particle_vec<D>(xs, 0);
    const Vec<D> d1 = particle_vec<D>(xe, 1) - particle_vec<D>(xs, 1);
    const Vec<D> d2 = particle_vec<D>(xe, 2) - particle_vec<D>(xs, 2);
    const double tol = 1e-12;
    {  // particle-particle (0, 1)
      const auto p = swept_polynomials<D>(model, {CollisionKind::kParticleParticle, 0, 1}, xs, xe);
      ASSERT_EQ(p.size(), 2u);
      const double R = r0 + model.particle_radius[1];
      EXPECT_NEAR(p[0](t), R * R - (x1 - x0).squaredNorm(), tol);
      EXPECT_NEAR(p[1](t), -(d1 - d0).dot(x1 - x0), tol);  // (v_0 - v_1)·n
    }
    {  // particle-half-plane (0, 0)
      const HalfPlane& plane = model.half_planes[0];
      const Vec<D> P = plane.point.head<D>(), N = plane.normal.head<D>();
      const auto p = swept_polynomials<D>(model, {CollisionKind::kParticleHalfPlane, 0, 0}, xs, xe);
      ASSERT_EQ(p.size(), 2u);
      const double q = (P - x0).dot(N);
      EXPECT_NEAR(p[0](t), r0 * r0 * N.dot(N) - q * q, tol);
      EXPECT_NEAR(p[1](t), d0.dot(N) * q, tol);  // v·n times (N·N)² / ... > 0 iff approaching
    }
    {  // particle-edge (0, edge 0 = (1, 2))
      const auto p = swept_polynomials<D>(model, {CollisionKind::kParticleEdge, 0, 0}, xs, xe);
      ASSERT_EQ(p.size(), 4u);
      const double R = r0 + model.edge_radius[0];
      const Vec<D> g = x2 - x1, u = x0 - x1, dg = d2 - d1;
      const double gg = g.squaredNorm();
      const double alpha = u.dot(g) / gg;  // unclamped
      const Vec<D> n = x1 + alpha * g - x0;
      EXPECT_NEAR(p[0](t), (R * R - n.squaredNorm()) * gg, tol);
      EXPECT_NEAR(p[1](t), u.dot(g), tol);
      EXPECT_NEAR(p[2](t), (x0 - x2).dot(x1 - x2), tol);
      // The exact approach polynomial, ‖g‖⁴ (Δx_0 - Δx_1 - α dg)·n, differs from the course's
      // in the t³ coefficient only: the course has -2FGQ where the exact one has -2FHQ.
      const double exact = gg * gg * (d0 - d1 - alpha * dg).dot(n);
      const Vec<D> u0 = particle_vec<D>(xs, 0) - particle_vec<D>(xs, 1);
      const Vec<D> g0 = particle_vec<D>(xs, 2) - particle_vec<D>(xs, 1);
      const Vec<D> du = d0 - d1;
      const double F = u0.dot(g0), G = u0.dot(dg) + du.dot(g0), H = du.dot(dg), Q = dg.dot(dg);
      const double quirk = (-2.0 * F * G * Q + 2.0 * F * H * Q) * t * t * t;
      EXPECT_NEAR(p[3](t), exact + quirk, 1e-11) << "t = " << t;
    }
  }
}

TEST(SweptDetection, PolynomialsMatchDirectEvaluationAlongTheStep) {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    expect_polynomials_match_direct_evaluation<2>(seed);
    expect_polynomials_match_direct_evaluation<3>(seed);
  }
}

TEST(SweptDetection, LeadingCoefficientsBelowOneInATrillionAreDropped) {
  EXPECT_EQ(Polynomial({1e-13, -9e-13, 2.0, 0.0}).coefficients(), (std::vector<double>{2.0, 0.0}));
  EXPECT_EQ(Polynomial({-9e-13, 3.0}).degree(), 0);
  EXPECT_EQ(Polynomial({-1e-12, 3.0}).degree(), 1);  // only below 1e-12 is dropped
  EXPECT_TRUE(Polynomial({0.0, 1e-13}).empty());
  // Two particles at rest: the overlap polynomial is a constant, the approach one is empty.
  TestScene scene(2);
  scene.add_particle(1, vec({0, 0}), vec({0, 0}), false, 0.5);
  scene.add_particle(1, vec({0.5, 0}), vec({0, 0}), false, 0.5);
  const auto p = swept_polynomials<2>(scene.model, {CollisionKind::kParticleParticle, 0, 1},
                                      scene.initial.q, scene.initial.q);
  EXPECT_EQ(p[0].degree(), 0);
  EXPECT_TRUE(p[1].empty());
}

TEST(Intervals, PositiveIntervalsFollowTheCourseRules) {
  // -(t - 1)(t - 3) > 0 on (1, 3); (t - 1)(t - 3) > 0 outside.
  EXPECT_EQ(positive_intervals(Polynomial({-1, 4, -3})), (std::vector<Interval>{{1, 3}}));
  EXPECT_EQ(positive_intervals(Polynomial({1, -4, 3})),
            (std::vector<Interval>{{-kInf, 1}, {3, kInf}}));
  EXPECT_EQ(positive_intervals(Polynomial({2})), (std::vector<Interval>{{-kInf, kInf}}));
  EXPECT_TRUE(positive_intervals(Polynomial({-2})).empty());
  EXPECT_TRUE(positive_intervals(Polynomial()).empty());
  EXPECT_EQ(positive_intervals(Polynomial({1, 0, 1})), (std::vector<Interval>{{-kInf, kInf}}));
  // A double root: positive on both sides, and the touching intervals merge.
  EXPECT_EQ(positive_intervals(Polynomial({1, -2, 1})), (std::vector<Interval>{{-kInf, kInf}}));
  // A root at exactly 0 from a zero constant term.
  EXPECT_EQ(positive_intervals(Polynomial({1, 0})), (std::vector<Interval>{{0, kInf}}));
}

TEST(Intervals, IntersectionKeepsTouchingPointsAndFirstTimeSkipsThePast) {
  EXPECT_EQ(intersect_intervals({{0, 1}, {2, 3}}, {{1, 2.5}}),
            (std::vector<Interval>{{1, 1}, {2, 2.5}}));
  EXPECT_EQ(first_time({{-3, -1}, {-0.5, 0.25}}), 0.0);
  EXPECT_EQ(first_time({{-3, 0}, {0.5, 2}}), 0.5);  // an interval ending at 0 is the past
  EXPECT_EQ(first_time({}), kInf);
}

TEST(ContinuousTime, CourseWorkedExampleTwoBalls) {
  // Radius 0.2 each, x0 = -0.41 moving +1, x1 = 0 at rest, explicit Euler h = 0.01: contact at
  // the very end of the step (the course's program reports t = 0.9999999999999443; the exact
  // root of its polynomial is 0.99999999999999164).
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({-0.41, 0}), vec({1, 0}), false, 0.2);
  scene.add_particle(1, vec({0, 0}), vec({0, 0}), false, 0.2);
  scene.model.collisions.method = &contact_method("continuous-time");
  StepPipeline pipeline(scene.model);
  StepRecord record;
  pipeline.step(scene.initial, &record);
  ASSERT_EQ(record.collisions.size(), 1u);
  EXPECT_NEAR(record.collisions[0].time, 0.99999999999999164, 1e-15);
  EXPECT_NEAR(record.collisions[0].normal[0], 0.4, 1e-15);
  EXPECT_NEAR(scene.initial.q[0], -0.40999999999999948, 1e-15);
  EXPECT_NEAR(scene.initial.v[0], -8.88e-16, 1e-17);
  EXPECT_EQ(scene.initial.q[2], 0.010000000000000009);
  EXPECT_EQ(scene.initial.v[2], 1.0000000000000009);
  EXPECT_EQ(record.polynomials.size(), 2u);  // N(N - 1)
  ASSERT_TRUE(record.sync);
  EXPECT_EQ(record.sync->q, scene.initial.q);
  EXPECT_EQ(record.sync->polynomials_logged, 2u);
}

TEST(ContinuousTime, CatchesAFastParticleThatDiscreteDetectionMisses) {
  for (const ContactMethod* method :
       {&contact_method("simple"), &contact_method("continuous-time")}) {
    TestScene scene(2, "explicit-euler", 0.01);
    scene.add_particle(1, vec({-0.5, 0}), vec({100, 0}), false, 0.05);  // 1 m per step
    scene.add_particle(1, vec({0, 0}), vec({0, 0}), true, 0.05);
    scene.model.collisions.method = method;
    StepPipeline pipeline(scene.model);
    StepRecord record;
    pipeline.step(scene.initial, &record);
    if (method == &contact_method("simple")) {
      EXPECT_TRUE(record.collisions.empty());  // it tunnelled through
      EXPECT_GT(scene.initial.q[0], 0.4);
    } else {
      ASSERT_EQ(record.collisions.size(), 1u);
      EXPECT_NEAR(record.collisions[0].time, 0.4, 1e-12);
      EXPECT_LT(scene.initial.q[0], -0.1);  // bounced back
      EXPECT_NEAR(scene.initial.v[0], -100.0, 1e-9);
    }
  }
}

TEST(Hybrid, CourseWorkedExampleThreeBallsWithOneImpulsePass) {
  // maxiters = 1, k = 0: the impulse pass answers (0, 1) only; the geometric stage finds (1, 2)
  // and moves {1, 2} rigidly.
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({-0.45, 0}), vec({1, 0}), false, 0.25);
  scene.add_particle(1, vec({0, 0}), vec({0, 0}), false, 0.25);
  scene.add_particle(1, vec({0.45, 0}), vec({0, 0}), false, 0.25);
  scene.model.collisions.method = &contact_method("hybrid");
  scene.model.collisions.max_iterations = 1;
  scene.model.collisions.stiffness = 0.0;
  scene.model.collisions.thickness = 0.1;
  StepPipeline pipeline(scene.model);
  StepRecord record;
  pipeline.step(scene.initial, &record);
  ASSERT_TRUE(record.sync);
  EXPECT_NEAR(record.sync->v[2], 1.0, 1e-15);
  EXPECT_EQ(record.sync->polynomials_logged, 6u);
  EXPECT_EQ(record.polynomials.size(), 18u);
  EXPECT_TRUE(record.collisions.empty());
  EXPECT_NEAR(scene.initial.q[2], 0.005, 1e-15);
  EXPECT_NEAR(scene.initial.q[4], 0.455, 1e-15);
  EXPECT_NEAR(scene.initial.v[2], 0.5, 1e-15);
  EXPECT_NEAR(scene.initial.v[4], 0.5, 1e-15);
}

TEST(Hybrid, PassesThatChangeNothingStopAtMaxIterationsAndTheZonesEnd) {
  // COR = -1 cancels every impulse: each pass finds the same collisions and leaves the state as
  // it was (a hostile scene's endless loop). The passes end at max_iterations, the largest the
  // loader accepts (io/collision_elements.cpp), with a log of 6 polynomials a pass, and the
  // geometric stage that follows ends too.
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({-0.3, 0}), vec({5, 0}), false, 0.25);
  scene.add_particle(1, vec({0, 0}), vec({0, 0}), false, 0.25);
  scene.add_particle(1, vec({0.3, 0}), vec({-5, 0}), false, 0.25);
  scene.model.collisions.method = &contact_method("hybrid");
  scene.model.collisions.max_iterations = 1000;
  scene.model.collisions.cor = -1.0;
  scene.model.collisions.stiffness = 0.0;
  scene.model.collisions.thickness = 0.1;
  StepPipeline pipeline(scene.model);
  StepRecord record;
  pipeline.step(scene.initial, &record);
  ASSERT_TRUE(record.sync);
  EXPECT_EQ(record.sync->polynomials_logged, 6000u);
  EXPECT_GT(record.polynomials.size(), 6000u);  // the geometric stage's passes
  EXPECT_LT(record.polynomials.size(), 6000u + 6u * 10u);
  // All three in one zone, moved rigidly: momentum (zero) is kept, the balls stop.
  EXPECT_NEAR(scene.initial.v.norm(), 0.0, 1e-12);
}

TEST(Hybrid, ZonesTouchingAHalfPlaneOrAFixedParticleStopDead) {
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({0, 0.3}), vec({0, -50}), false, 0.1);
  scene.add_half_plane(vec({0, 0}), vec({0, 1}));
  scene.model.collisions.method = &contact_method("hybrid");
  scene.model.collisions.max_iterations = 0;  // straight to the geometric stage
  StepPipeline pipeline(scene.model);
  pipeline.step(scene.initial);
  EXPECT_EQ(scene.initial.q[1], 0.3);
  EXPECT_EQ(scene.initial.v[1], 0.0);
}

TEST(Hybrid, RigidFailsafeKeepsTheZonesShapeMomentumAndAngularMomentum) {
  // Three particles (masses 1, 2, 3) whose integrated positions moved and deformed: the zone
  // moves rigidly, its centre of mass goes where the integrated one went, and the rotation is
  // ω = L/I, so the angular momentum of the displacements about the centre is kept.
  TestScene scene(2, "explicit-euler", 0.1);
  scene.add_particle(1, vec({-1, 0}), vec({0, 0}));
  scene.add_particle(2, vec({1, 0}), vec({0, 0}));
  scene.add_particle(3, vec({0, 1}), vec({0, 0}));
  const Vector xs = scene.initial.q;
  Vector q = xs + vec({0.1, -0.05, 0.2, 0.15, -0.1, 0.1});
  Vector v = Vector::Zero(6);
  const ImpactZone zone = merge_impact_zones(
      {impact_zone_of(scene.model, {CollisionKind::kParticleParticle, 0, 1}),
       impact_zone_of(scene.model, {CollisionKind::kParticleParticle, 1, 2})})[0];
  ASSERT_EQ(zone.particles, (std::vector<int>{0, 1, 2}));
  const Vector integrated = q;
  apply_rigid_failsafe(scene.model, zone, xs, 0.1, q, v);
  const auto point = [](const Vector& x, int p) -> Vec<2> { return x.segment<2>(2 * p); };
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      EXPECT_NEAR((point(q, a) - point(q, b)).norm(), (point(xs, a) - point(xs, b)).norm(), 1e-14);
    }
    testing::expect_close(point(v, a), (point(q, a) - point(xs, a)) / 0.1, 1e-13, "velocity");
  }
  const double m[3] = {1, 2, 3};
  Vec<2> cm_xs = Vec<2>::Zero(), cm_q = Vec<2>::Zero(), cm_int = Vec<2>::Zero();
  for (int p = 0; p < 3; ++p) {
    cm_xs += m[p] * point(xs, p) / 6.0;
    cm_q += m[p] * point(q, p) / 6.0;
    cm_int += m[p] * point(integrated, p) / 6.0;
  }
  EXPECT_NEAR((cm_q - cm_int).norm(), 0.0, 1e-14);
  // The rotation angle is L/I with the displacements relative to the centre's.
  double L = 0.0, I = 0.0;
  for (int p = 0; p < 3; ++p) {
    const Vec<2> r = point(xs, p) - cm_xs;
    const Vec<2> d = point(integrated, p) - point(xs, p) - (cm_int - cm_xs);
    L += m[p] * (r.x() * d.y() - r.y() * d.x());
    I += m[p] * r.squaredNorm();
  }
  const Vec<2> r0 = point(xs, 0) - cm_xs, r0_now = point(q, 0) - cm_q;
  EXPECT_NEAR(std::atan2(r0.x() * r0_now.y() - r0.y() * r0_now.x(), r0.dot(r0_now)), L / I, 1e-14);
}

}  // namespace
}  // namespace fosssim
