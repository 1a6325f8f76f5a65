// Discrete detection and impulses (type simple) against hand computation and conservation laws.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/impulses.h"
#include "core/collisions/proximity.h"
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

/// Takes one step of the scene through its pipeline; returns the step's record.
StepRecord step_scene_once(TestScene& scene) {
  StepPipeline pipeline(scene.model);
  StepRecord record;
  pipeline.step(scene.initial, &record);
  return record;
}

TEST(SimpleCollisions, CourseWorkedExampleParticleEdgeWithRestitutionHalf) {
  // Particle 0 (m 2, r 0.1) falls onto an edge from fixed particle 1 to particle 2 (m 3), edge
  // radius 0.1, explicit Euler h = 0.1, COR 0.5: the course's program gives these velocities.
  TestScene scene(2, "explicit-euler", 0.1);
  scene.add_particle(2, vec({0.3, 0.25}), vec({0, -1}), false, 0.1);
  scene.add_particle(1, vec({-1, 0}), vec({0, 0}), true, 0.1);
  scene.add_particle(3, vec({1, 0}), vec({0, 0}), false, 0.1);
  scene.add_edge(1, 2, 0.1);
  scene.model.collisions.method = &contact_method("simple");
  scene.model.collisions.cor = 0.5;
  const StepRecord record = step_scene_once(scene);
  EXPECT_EQ(scene.initial.v[1], 0.17035110533159936);
  EXPECT_EQ(scene.initial.v[5], -0.50715214564369315);
  ASSERT_EQ(record.collisions.size(), 1u);
  EXPECT_EQ(record.collisions[0].kind, CollisionKind::kParticleEdge);
  EXPECT_EQ(record.collisions[0].first, 0);
  EXPECT_EQ(record.collisions[0].second, 0);
  EXPECT_NEAR(record.collisions[0].normal[1], -0.15, 1e-15);
  EXPECT_EQ(record.collisions[0].time, 0.0);
  // Hand evaluation: α = 0.65, n̂ = (0, -1) up to round-off, s = 2 (0 - (-1))·(-1) = -2,
  // c = 0.75: Δv_0 = c s / (1 + α² M_0/M_2) n̂, Δv_2 = -c α s / (M_2/M_0 + α²) n̂.
  const double alpha = 0.65, c = 0.75, s = -2.0;
  EXPECT_NEAR(scene.initial.v[1], -1.0 - c * s / (1.0 + alpha * alpha * 2.0 / 3.0), 1e-14);
  EXPECT_NEAR(scene.initial.v[5], -(-c * alpha * s / (3.0 / 2.0 + alpha * alpha)), 1e-14);
}

TEST(SimpleCollisions, TouchingExactlyOrMovingApartIsNotACollision) {
  for (const double vx : {1.0, 0.0, -1.0}) {
    TestScene scene(2, "explicit-euler", 0.01);
    // Radii 0.5 + 0.25 = 0.75, exactly the distance at the end of the step when vx = 0.
    scene.add_particle(1, vec({0, 0}), vec({vx, 0}), false, 0.5);
    scene.add_particle(1, vec({0.75, 0}), vec({0, 0}), false, 0.25);
    scene.model.collisions.method = &contact_method("simple");
    const StepRecord record = step_scene_once(scene);
    // vx = 1: overlapping and approaching; 0: touching exactly; -1: overlapping, moving apart.
    EXPECT_EQ(record.collisions.size(), vx > 0.0 ? 1u : 0u) << "vx = " << vx;
  }
}

TEST(SimpleCollisions, CentreOnAnEdgeOrABoundaryIsNeverDetected) {
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({0, 0}), vec({0, -1e-12}), false, 0.1);
  scene.add_particle(1, vec({-1, 0}), vec({0, 0}), true);
  scene.add_particle(1, vec({1, 0}), vec({0, 0}), true);
  scene.add_edge(1, 2, 0.1);
  scene.add_half_plane(vec({0, 0}), vec({0, 1}));
  scene.initial.v.setZero();
  scene.model.collisions.method = &contact_method("simple");
  EXPECT_TRUE(step_scene_once(scene).collisions.empty());
}

TEST(SimpleCollisions, HalfPlaneDistanceIsUnsigned) {
  // The solid is y ≤ 0. A particle whose centre is below the boundary and moves deeper is not
  // detected; one below the boundary moving back up is "approaching" and pushed back in.
  for (const double vy : {-1.0, 1.0}) {
    TestScene scene(2, "explicit-euler", 0.001);
    scene.add_particle(1, vec({0, -0.05}), vec({0, vy}), false, 0.1);
    scene.add_half_plane(vec({0, 0}), vec({0, 2}));  // the normal's length does not matter
    scene.model.collisions.method = &contact_method("simple");
    const StepRecord record = step_scene_once(scene);
    if (vy < 0.0) {
      EXPECT_TRUE(record.collisions.empty());
      EXPECT_EQ(scene.initial.v[1], -1.0);
    } else {
      ASSERT_EQ(record.collisions.size(), 1u);
      EXPECT_GT(record.collisions[0].normal[1], 0.0);  // towards the boundary, above
      EXPECT_EQ(scene.initial.v[1], -1.0);               // reflected: deeper into the solid
    }
  }
}

TEST(SimpleCollisions, GaussSeidelInTheCourseOrderPassesMomentumAlongAChain) {
  // Three equal balls in a row, overlapping, the first moving: the pair (0, 1) is answered
  // first, then (1, 2) sees particle 1's new velocity and passes it on.
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({-0.45, 0}), vec({1, 0}), false, 0.25);
  scene.add_particle(1, vec({0, 0}), vec({0, 0}), false, 0.25);
  scene.add_particle(1, vec({0.45, 0}), vec({0, 0}), false, 0.25);
  scene.model.collisions.method = &contact_method("simple");
  const StepRecord record = step_scene_once(scene);
  ASSERT_EQ(record.collisions.size(), 2u);
  EXPECT_EQ(record.collisions[0].second, 1);
  EXPECT_EQ(record.collisions[1].first, 1);
  EXPECT_EQ(record.collisions[1].second, 2);
  EXPECT_NEAR(scene.initial.v[0], 0.0, 1e-15);
  EXPECT_NEAR(scene.initial.v[2], 0.0, 1e-15);
  EXPECT_NEAR(scene.initial.v[4], 1.0, 1e-15);
}

TEST(SimpleCollisions, FixedParticlesHaveInfiniteMassAndDoNotMove) {
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({0, 0}), vec({1, 0}), false, 0.2);
  scene.add_particle(7, vec({0.35, 0}), vec({0, 0}), true, 0.2);
  scene.model.collisions.method = &contact_method("simple");
  step_scene_once(scene);
  EXPECT_EQ(scene.initial.v[0], -1.0);  // reflected as from a wall
  EXPECT_EQ(scene.initial.v[1], 0.0);
  EXPECT_EQ(scene.initial.v[2], 0.0);
  EXPECT_EQ(scene.initial.v[3], 0.0);
}

TEST(SimpleCollisions, FixedParticleAgainstAnEdgeWithAFixedEndGivesTheCoursesNaN) {
  // Course-compatible degenerate case: alpha clamped to 0 with both the particle and the
  // edge's first end fixed makes 0/0 in the free end's update.
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({-0.1, 0}), vec({1, 0}), true, 0.2);
  scene.add_particle(1, vec({0, 0}), vec({0, 0}), true, 0.1);
  scene.add_particle(1, vec({1, 0}), vec({0, 0}), false, 0.1);
  const int e = scene.add_edge(1, 2, 0.1);
  const CandidatePair pair{CollisionKind::kParticleEdge, 0, e};
  const Separation<2> s = separation<2>(scene.model, pair, scene.initial.q);
  EXPECT_EQ(s.alpha, 0.0);
  const auto w = [&](int p) -> Vec<2> { return scene.initial.v.segment<2>(2 * p); };
  const Impulse<2> impulse = compute_impulse<2>(scene.model, pair, s.n, s.alpha, w, 1.0);
  ASSERT_EQ(impulse.count, 1);
  EXPECT_EQ(impulse.particle[0], 2);
  EXPECT_TRUE(std::isnan(impulse.dv[0][0]));
}

template <int D>
void expect_elastic_impulses_conserve_momentum_and_energy() {
  Random random(7 + D);
  for (int trial = 0; trial < 200; ++trial) {
    TestScene scene(D);
    const int n = 3;
    for (int p = 0; p < n; ++p) {
      scene.add_particle(random.uniform(0.5, 3.0), random.uniform_vector(D, -1, 1),
                         random.uniform_vector(D, -1, 1), false, 0.5);
    }
    scene.add_edge(1, 2);
    const SceneModel& model = scene.model;
    const auto w = [&](int p) -> Vec<D> { return scene.initial.v.template segment<D>(D * p); };
    for (const CandidatePair pair : {CandidatePair{CollisionKind::kParticleParticle, 0, 1},
                                     CandidatePair{CollisionKind::kParticleEdge, 0, 0}}) {
      const Separation<D> s = separation<D>(model, pair, scene.initial.q);
      const Impulse<D> impulse = compute_impulse<D>(model, pair, s.n, s.alpha, w, 1.0);
      Vector v = scene.initial.v;
      for (int k = 0; k < impulse.count; ++k) {
        v.template segment<D>(D * impulse.particle[k]) += impulse.dv[k];
      }
      testing::expect_close(testing::linear_momentum(model, v),
                            testing::linear_momentum(model, scene.initial.v), 1e-13, "momentum");
      const double before = 0.5 * scene.initial.v.dot(model.mass.cwiseProduct(scene.initial.v));
      const double after = 0.5 * v.dot(model.mass.cwiseProduct(v));
      EXPECT_NEAR(after, before, 1e-12 * (1.0 + before)) << "trial " << trial;
    }
  }
}

TEST(SimpleCollisions, ElasticImpulsesConserveMomentumAndKineticEnergy2D) {
  expect_elastic_impulses_conserve_momentum_and_energy<2>();
}
TEST(SimpleCollisions, ElasticImpulsesConserveMomentumAndKineticEnergy3D) {
  expect_elastic_impulses_conserve_momentum_and_energy<3>();
}

template <int D>
void expect_no_overlap_missed(unsigned seed) {
  // Every overlapping pair (brute force over all pairs and the definition of overlap) is among
  // the candidates; the candidates hold no pair twice and no particle against its own edge.
  Random random(seed);
  TestScene scene(D);
  const int n = 40;
  for (int p = 0; p < n; ++p) {
    scene.add_particle(1, random.uniform_vector(D, -2, 2), random.uniform_vector(D, -1, 1),
                       p % 7 == 0, random.uniform(0.05, 0.4));
  }
  for (int e = 0; e < 15; ++e) {
    const int i = static_cast<int>(random.uniform(0, n)), j = (i + 1 + e) % n;
    scene.add_edge(i, j, random.uniform(0.01, 0.2));
  }
  for (int h = 0; h < 3; ++h) {
    scene.add_half_plane(random.uniform_vector(D, -2, 2), random.uniform_vector(D, -1, 1));
  }
  const SceneModel& model = scene.model;
  const auto pairs = make_candidate_pairs(model);
  std::vector<CandidatePair> seen;
  pairs->for_each(PairQuery{scene.initial.q, scene.initial.q, 0.0},
                  [&seen](const CandidatePair& pair) { seen.push_back(pair); });
  const auto has = [&seen](const CandidatePair& pair) {
    return std::count(seen.begin(), seen.end(), pair);
  };
  int overlaps = 0;
  for (int i = 0; i < n; ++i) {
    const auto check = [&](const CandidatePair& pair) {
      const Separation<D> s = separation<D>(model, pair, scene.initial.q);
      if (s.n.norm() < s.radii) {
        ++overlaps;
        EXPECT_EQ(has(pair), 1);
      }
    };
    for (int j = i + 1; j < n; ++j) check({CollisionKind::kParticleParticle, i, j});
    for (int e = 0; e < static_cast<int>(model.edges.size()); ++e) {
      const bool endpoint = model.edges[e].i == i || model.edges[e].j == i;
      if (endpoint) {
        EXPECT_EQ(has({CollisionKind::kParticleEdge, i, e}), 0);
      } else {
        check({CollisionKind::kParticleEdge, i, e});
      }
    }
    for (int h = 0; h < 3; ++h) check({CollisionKind::kParticleHalfPlane, i, h});
  }
  EXPECT_GT(overlaps, 10);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end(), precedes_in_course_order));
}

TEST(CandidatePairs, NoOverlapMissedOnRandomScenes) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    expect_no_overlap_missed<2>(seed);
    expect_no_overlap_missed<3>(seed);
  }
}

TEST(Collisions3D, HalfSpacesParticlesAndEdgesWithEveryMethodButHybrid) {
  // A ball falls onto the half-space z ≤ 0 (normal of length 3) in 3D: simple impulses reflect
  // it; continuous-time catches it even when it would pass the floor within one step; the
  // penalty force pushes it up.
  for (const ContactMethod* method : {&contact_method("simple"), &contact_method("continuous-time"),
                                      &contact_method("penalty")}) {
    TestScene scene(3, "explicit-euler", 0.01);
    const double speed = method == &contact_method("continuous-time") ? 50.0 : 1.0;
    scene.add_particle(1, vec({0.1, -0.2, 0.05}), vec({0.3, 0, -speed}), false, 0.1);
    scene.add_half_plane(vec({0, 0, 0}), vec({0, 0, 3}));
    scene.model.collisions.method = method;
    StepPipeline pipeline(scene.model);
    StepRecord record;
    pipeline.step(scene.initial, &record);
    if (method == &contact_method("penalty")) {
      EXPECT_GT(scene.initial.v[2], -speed) << "pushed up";
      continue;
    }
    ASSERT_EQ(record.collisions.size(), 1u);
    EXPECT_EQ(record.collisions[0].kind, CollisionKind::kParticleHalfPlane);
    EXPECT_EQ(record.collisions[0].normal.size(), 3);
    EXPECT_NEAR(scene.initial.v[2], speed, 1e-9);
    EXPECT_NEAR(scene.initial.v[0], 0.3, 1e-15);
  }
  // A particle against a particle and an edge in 3D, with simple impulses.
  TestScene scene(3, "explicit-euler", 0.01);
  scene.add_particle(1, vec({0, 0, 0.15}), vec({0, 0, -1}), false, 0.1);
  scene.add_particle(1, vec({-1, 0, 0}), vec({0, 0, 0}), true, 0.05);
  scene.add_particle(1, vec({1, 0, 0}), vec({0, 0, 0}), true, 0.05);
  scene.add_edge(1, 2, 0.1);
  scene.add_particle(1, vec({0.12, 0, 0.25}), vec({-2, 0, 0}), false, 0.1);
  scene.model.collisions.method = &contact_method("simple");
  StepPipeline pipeline(scene.model);
  StepRecord record;
  pipeline.step(scene.initial, &record);
  // In the course's order: particle 0 against particle 3, then against the edge.
  ASSERT_EQ(record.collisions.size(), 2u);
  EXPECT_EQ(record.collisions[0].kind, CollisionKind::kParticleParticle);
  EXPECT_EQ(record.collisions[0].second, 3);
  EXPECT_EQ(record.collisions[1].kind, CollisionKind::kParticleEdge);
}

TEST(SimpleCollisions, WorkedExampleE3HalfPlaneNormalAndImpulseAreTheCoursesBits) {
  // The course's program on this scene records n = (-0.12499999999999997, ...) (the normal
  // made a unit vector by its reciprocal length) and bounces to these velocities; the naive
  // ((P - x)·N ÷ N·N) N and n ÷ ‖n‖ give n = (-0.125, -0.125) and v = (1.2499999999999996, ...).
  TestScene scene(2, "explicit-euler", 1e-20);
  scene.add_particle(1, vec({-0.9, -0.85}), vec({-1, -2}), false, 0.2);
  scene.add_half_plane(vec({-1, -1}), vec({1, 1}));
  scene.model.collisions.method = &contact_method("simple");
  scene.model.collisions.cor = 0.5;
  const StepRecord record = step_scene_once(scene);
  ASSERT_EQ(record.collisions.size(), 1u);
  EXPECT_EQ(record.collisions[0].kind, CollisionKind::kParticleHalfPlane);
  EXPECT_EQ(record.collisions[0].normal[0], -0.12499999999999997);
  EXPECT_EQ(record.collisions[0].normal[1], -0.12499999999999997);
  EXPECT_EQ(scene.initial.v[0], 1.2500000000000004);
  EXPECT_EQ(scene.initial.v[1], 0.25000000000000044);
}

TEST(SimpleCollisions, AFixedParticleBouncesOffAHalfPlaneAndThenMoves) {
  // The course's rule: a half-plane's impulse applies to a fixed particle too. With h = 1/16
  // the particle reaches y = 0.125 (n = (-0, -0.125), n̂ = (-0, -1) exactly) and leaves with
  // v = -1 + 1.5 = 0.5; the next step moves it by h · 0.5.
  TestScene scene(2, "explicit-euler", 0.0625);
  scene.add_particle(1, vec({0, 0.1875}), vec({0, -1}), true, 0.2);
  scene.add_half_plane(vec({0, 0}), vec({0, 1}));
  scene.model.collisions.method = &contact_method("simple");
  scene.model.collisions.cor = 0.5;
  const StepRecord record = step_scene_once(scene);
  ASSERT_EQ(record.collisions.size(), 1u);
  EXPECT_EQ(scene.initial.q[1], 0.125);
  EXPECT_EQ(scene.initial.v[0], 0.0);
  EXPECT_EQ(scene.initial.v[1], 0.5);
  step_scene_once(scene);
  EXPECT_EQ(scene.initial.q[1], 0.15625);
  EXPECT_EQ(scene.initial.v[1], 0.5);
}

}  // namespace
}  // namespace fosssim
