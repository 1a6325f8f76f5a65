// Static spheres against hand computation: the separation and the impulse, the penalty force
// and its derivatives, and swept detection's polynomials, roots and response.

#include <gtest/gtest.h>

#include <cmath>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/penalty_force.h"
#include "core/collisions/swept_detection.h"
#include "core/force_evaluation.h"
#include "core/force_set.h"
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

/// One particle of mass m and radius r at x with velocity v, and the sphere of radius 1 about
/// the origin.
TestScene particle_and_sphere(const Vector& x, const Vector& v, double r,
                              const ContactMethod* method, double h = 0.01) {
  TestScene scene(3, "explicit-euler", h);
  scene.add_particle(2.0, x, v, false, r);
  scene.model.spheres.push_back({vec({0, 0, 0}), 1.0});
  scene.model.collisions.method = method;
  return scene;
}

TEST(SphereContact, PairsComeAfterHalfPlanesInTheCourseOrder) {
  TestScene scene(3);
  scene.add_particle(1, vec({0, 0, 0}), vec({0, 0, 0}));
  scene.add_particle(1, vec({1, 0, 0}), vec({0, 0, 0}));
  scene.add_half_plane(vec({0, 0, 0}), vec({0, 1, 0}));
  scene.model.spheres.push_back({vec({0, 5, 0}), 1.0});
  std::vector<CandidatePair> visited;
  AllPairs(scene.model)
      .for_each(PairQuery{scene.initial.q, scene.initial.q},
                [&](const CandidatePair& p) { visited.push_back(p); });
  const std::vector<CandidatePair> expected = {{CollisionKind::kParticleParticle, 0, 1},
                                               {CollisionKind::kParticleHalfPlane, 0, 0},
                                               {CollisionKind::kParticleSphere, 0, 0},
                                               {CollisionKind::kParticleHalfPlane, 1, 0},
                                               {CollisionKind::kParticleSphere, 1, 0}};
  EXPECT_EQ(visited, expected);
  for (std::size_t k = 1; k < visited.size(); ++k) {
    EXPECT_TRUE(precedes_in_course_order(visited[k - 1], visited[k]));
  }
}

TEST(SphereContact, SimpleImpulseMatchesHandComputation) {
  // x = (0.3, 1.05, 0), r = 0.1: n = -x, ‖n‖² = 1.1925 < 1.1², v·n = 1.8 > 0 (approaching).
  // With COR 0.5, c = 0.75: v' = v - 2c (v·n̂) n̂ = v - 1.5 · 1.8 / 1.1925 · n.
  TestScene scene = particle_and_sphere(vec({0.3, 1.05, 0}), vec({1, -2, 0}), 0.1,
                                        &contact_method("simple"), 1e-12);
  scene.model.collisions.cor = 0.5;
  StepPipeline pipeline(scene.model);
  StepRecord record;
  pipeline.step(scene.initial, &record);
  const Vector n = -vec({0.3, 1.05, 0});  // the step of 1e-12 s moves nothing that matters
  const Vector expected = vec({1, -2, 0}) - (1.5 * 1.8 / 1.1925) * n;
  testing::expect_close(scene.initial.v, expected, 1e-10, "velocity after the impulse");
  ASSERT_EQ(record.collisions.size(), 1u);
  EXPECT_EQ(record.collisions[0].kind, CollisionKind::kParticleSphere);
  testing::expect_close(record.collisions[0].normal, n, 1e-10, "recorded normal");
  // The normal velocity is reversed and halved, the tangential one kept.
  const Vector nhat = n / n.norm();
  EXPECT_NEAR(scene.initial.v.dot(nhat), -0.5 * vec({1, -2, 0}).dot(nhat), 1e-10);
}

TEST(SphereContact, NoCollisionWhenTouchingExactlyOrMovingAway) {
  // ‖n‖ = 1.1 = radii exactly (strict inequality); then overlapping but leaving.
  for (const auto& [x, v] : {std::pair{vec({0, 1.1, 0}), vec({0, -1, 0})},
                             std::pair{vec({0, 1.05, 0}), vec({0, 1, 0})}}) {
    TestScene scene = particle_and_sphere(x, v, 0.1, &contact_method("simple"), 1e-300);
    StepPipeline pipeline(scene.model);
    StepRecord record;
    pipeline.step(scene.initial, &record);
    EXPECT_TRUE(record.collisions.empty());
  }
}

TEST(SphereContact, PenaltyForceMatchesHandComputation) {
  // d = ‖(0, 1.05, 0)‖ = 1.05, R = 1.1, T = 0.05: δ = -0.1, n̂ = (0, -1, 0): F = k δ n̂ = (0, 10, 0).
  TestScene scene =
      particle_and_sphere(vec({0, 1.05, 0}), vec({0, 0, 0}), 0.1, &contact_method("penalty"));
  scene.model.collisions.stiffness = 100.0;
  scene.model.collisions.thickness = 0.05;
  const Vector F = compute_force(ForceSet(scene.model), scene.initial.q, scene.initial.v);
  testing::expect_close(F, vec({0, 10, 0}), 1e-12, "penalty force");
  // Out of reach (d = 1.16 > R + T): nothing.
  scene.initial.q = vec({0, 1.16, 0});
  EXPECT_EQ(compute_force(ForceSet(scene.model), scene.initial.q, scene.initial.v).norm(), 0.0);
}

TEST(SphereContact, PenaltyJacobianMatchesFiniteDifferences) {
  Random random(11);
  for (int trial = 0; trial < 20; ++trial) {
    // A particle within reach of the sphere at a random direction, not at the support's edge.
    const Vector x = random.unit_vector(3) * random.uniform(0.6, 1.1);
    TestScene scene = particle_and_sphere(x, vec({0, 0, 0}), 0.1, &contact_method("penalty"));
    scene.model.collisions.thickness = 0.05;
    scene.model.collisions.penalty_jacobian = PenaltyJacobian::kExact;
    ForceSet forces(scene.model);
    const Force& penalty = *forces.forces().back();
    EXPECT_TRUE(testing::check_force_everywhere(
        penalty, 3, scene.initial.q, scene.initial.v, scene.model.mass,
        {"penalty(sphere)", "random", std::to_string(trial)}));
  }
}

TEST(SphereContact, SweptPolynomialsRootsAndResponse) {
  // A particle of radius 0.5 from (0, 3, 0) to (0, 0.5, 0) over the step: it touches the unit
  // sphere when its height is 1.5, at t = 0.6. With p = C - x_s = (0, -3, 0) and w = -Δx =
  // (0, 2.5, 0): overlap R² - ‖p + t w‖² = -6.25 t² + 15 t - 6.75 (roots 0.6 and 1.8) and
  // approach -w·w t - p·w = -6.25 t + 7.5 (positive before t = 1.2).
  const double h = 0.1;
  TestScene scene = particle_and_sphere(vec({0, 3, 0}), vec({0, -25, 0}), 0.5,
                                        &contact_method("continuous-time"), h);
  const Vector xs = scene.initial.q, xe = vec({0, 0.5, 0});
  const CandidatePair pair{CollisionKind::kParticleSphere, 0, 0};
  const auto polynomials = swept_polynomials<3>(scene.model, pair, xs, xe);
  ASSERT_EQ(polynomials.size(), 2u);
  EXPECT_EQ(polynomials[0].coefficients(), (std::vector<double>{-6.25, 15.0, -6.75}));
  EXPECT_EQ(polynomials[1].coefficients(), (std::vector<double>{-6.25, 7.5}));
  const auto hit = detect_swept<3>(scene.model, pair, xs, xe, nullptr);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->time, 0.6, 1e-15);
  testing::expect_close(hit->separation.n, vec({0, -1.5, 0}), 1e-14, "normal at t = 0.6");
  // Through the pipeline (explicit Euler moves x to exactly xe): COR 1 turns the displacement
  // velocity (0, -25, 0) around, V = (0, 25, 0), and X = xe + h·(0, 50, 0) = (0, 5.5, 0).
  StepPipeline pipeline(scene.model);
  StepRecord record;
  pipeline.step(scene.initial, &record);
  testing::expect_close(scene.initial.v, vec({0, 25, 0}), 1e-12, "velocity");
  testing::expect_close(scene.initial.q, vec({0, 5.5, 0}), 1e-12, "position");
  ASSERT_EQ(record.collisions.size(), 1u);
  EXPECT_EQ(record.collisions[0].kind, CollisionKind::kParticleSphere);
  EXPECT_NEAR(record.collisions[0].time, 0.6, 1e-15);
}

TEST(SphereContact, ContinuousTimeCatchesAParticleThatWouldPassThroughInOneStep) {
  // At 100 m/s a particle crosses the whole sphere within a step of 0.05 s: discrete detection
  // at the end sees nothing, swept detection stops it at the near side.
  for (const ContactMethod* method :
       {&contact_method("simple"), &contact_method("continuous-time")}) {
    TestScene scene = particle_and_sphere(vec({-3, 0.2, 0}), vec({100, 0, 0}), 0.1, method, 0.05);
    StepPipeline pipeline(scene.model);
    StepRecord record;
    pipeline.step(scene.initial, &record);
    if (method == &contact_method("simple")) {
      EXPECT_TRUE(record.collisions.empty());
      EXPECT_GT(scene.initial.q[0], 1.1);  // passed through
    } else {
      ASSERT_EQ(record.collisions.size(), 1u);
      EXPECT_LT(scene.initial.q[0], -1.0);  // turned back on the side it came from
      EXPECT_LT(scene.initial.v[0], 0.0);
    }
  }
}

}  // namespace
}  // namespace fosssim
