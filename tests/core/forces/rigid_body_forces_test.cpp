// Tests of the rigid-body forces (docs/rigid-bodies.md, 'Forces'): gravity, springs between
// body points or to world points, and wind sampled along edges.
//
// Math checked: gradE against finite differences of U, hessX against differences of gradE,
// hessV against differences in (V, ω), on random configurations (library checker and the
// full-matrix check); the generalized force equals (F, τ) written out by hand; a two-vertex
// stick gets the wind twice; the l = l0 = 0 spring exerts nothing.

#include <gtest/gtest.h>

#include <cmath>

#include "core/force_evaluation.h"
#include "core/forces/rigid_body_gravity_force.h"
#include "core/forces/rigid_body_spring_force.h"
#include "core/forces/rigid_body_wind_force.h"
#include "core/rigid_test_models.h"
#include "support/finite_differences.h"
#include "support/random.h"

namespace fosssim::testing {
namespace {

std::vector<BodySpec> random_bodies(Random& random, int count) {
  std::vector<BodySpec> specs;
  for (int b = 0; b < count; ++b) {
    BodySpec spec;
    const int n = 2 + b % 3;
    for (int k = 0; k < n; ++k) {
      spec.points.emplace_back(random.uniform(-2.0, 2.0) + 3.0 * b, random.uniform(-2.0, 2.0));
      spec.masses.push_back(random.uniform(0.5, 3.0));
    }
    specs.push_back(spec);
  }
  return specs;
}

/// A random state near the model's initial one: angles in [−π, π], velocities in [−1, 1].
void randomize(Random& random, Vector& q, Vector& v) {
  for (int k = 0; k < q.size(); ++k) {
    q[k] += k % 3 == 2 ? random.uniform(-M_PI, M_PI) : random.uniform(-0.5, 0.5);
    v[k] = random.uniform(-1.0, 1.0);
  }
}

TEST(RigidBodyGravityForceTest, ForceIsMassTimesAccelerationNoTorque) {
  auto [model, state] =
      make_rigid_model({{{{0, 0}, {2, 0}}, {1, 3}}, {{{0, 1}, {0, 2}, {1, 1}}, {1, 1, 2}}});
  const RigidBodyGravityForce gravity(Vec2(0.5, -9.81));
  const Vector gradient = gradient_of(gravity, state.q, state.v, model.mass);
  EXPECT_EQ(gradient[0], -4 * 0.5);
  EXPECT_EQ(gradient[1], 4 * 9.81);
  EXPECT_EQ(gradient[2], 0.0);
  EXPECT_EQ(gradient[3], -4 * 0.5);
  EXPECT_EQ(gradient[5], 0.0);
  // U = −Σ M g·X: X_0 = (1.5, 0), X_1 = (0.5, 1.25).
  EXPECT_NEAR(energy_of(gravity, state.q, state.v, model.mass),
              -4 * (0.5 * 1.5) - 4 * (0.5 * 0.5 - 9.81 * 1.25), 1e-13);
}

TEST(RigidBodyGravityForceTest, DerivativesOnRandomConfigurations) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    Random random(seed);
    auto [model, state] = make_rigid_model(random_bodies(random, 3));
    randomize(random, state.q, state.v);
    const RigidBodyGravityForce gravity(Vec2(random.uniform(-5, 5), random.uniform(-10, 0)));
    check_force_everywhere(gravity, 3, state.q, state.v, model.mass,
                           {"rigidbodygravity", "random", "seed " + std::to_string(seed)});
  }
}

TEST(RigidBodySpringForceTest, ForceAndTorqueByHand) {
  // A unit square at the origin, rotated by 90°; its attachment (1, 0) sits at (0, 1). World
  // point (0, 4), k = 2, l0 = 1: d = (0, 3), l = 3, f = 2·2·(0, 1) = (0, 4) on the body;
  // τ = (R p) × f = (0, 1) × (0, 4) = 0. Off-axis attachment (1, 1) → R p = (−1, 1):
  // d = (1, 3), l = √10, f = 2 (√10 − 1)(1, 3)/√10, τ = (−1, 1) × f.
  auto [model, state] = make_rigid_model({{{{-1, 1}, {1, 1}, {1, -1}, {-1, -1}}, {1, 1, 1, 1}}});
  state.q[2] = M_PI / 2;
  {
    const RigidBodySpringForce spring(0, Vec2(1, 0), -1, Vec2(0, 4), 2.0, 1.0);
    const Vector g = gradient_of(spring, state.q, state.v, model.mass);
    EXPECT_NEAR(-g[0], 0.0, 1e-15);
    EXPECT_NEAR(-g[1], 4.0, 1e-15);
    EXPECT_NEAR(-g[2], 0.0, 1e-15);
    EXPECT_NEAR(energy_of(spring, state.q, state.v, model.mass), 0.5 * 2 * 4, 1e-14);
  }
  {
    const RigidBodySpringForce spring(0, Vec2(1, 1), -1, Vec2(0, 4), 2.0, 1.0);
    const Vector g = gradient_of(spring, state.q, state.v, model.mass);
    const double l = std::sqrt(10.0);
    const Vec2 f = 2 * (l - 1) * Vec2(1, 3) / l;
    EXPECT_NEAR(-g[0], f.x(), 1e-14);
    EXPECT_NEAR(-g[1], f.y(), 1e-14);
    EXPECT_NEAR(-g[2], -1 * f.y() - 1 * f.x(), 1e-14);
  }
}

TEST(RigidBodySpringForceTest, ZeroRestLengthAtZeroLengthExertsNothing) {
  auto [model, state] = make_rigid_model({{{{0, 0}, {2, 0}}, {1, 1}}});
  // The attachment (0, 0) is the centre (1, 0); the world end is there too.
  const RigidBodySpringForce spring(0, Vec2(0, 0), -1, Vec2(1, 0), 5.0, 0.0);
  const Vector g = gradient_of(spring, state.q, state.v, model.mass);
  EXPECT_TRUE(g.isZero(0.0));
  EXPECT_EQ(energy_of(spring, state.q, state.v, model.mass), 0.0);
}

TEST(RigidBodySpringForceTest, DerivativesOnRandomConfigurations) {
  for (unsigned seed = 11; seed <= 16; ++seed) {
    Random random(seed);
    auto [model, state] = make_rigid_model(random_bodies(random, 3));
    randomize(random, state.q, state.v);
    const Vec2 pi(random.uniform(-1, 1), random.uniform(-1, 1));
    const Vec2 pj(random.uniform(-1, 1), random.uniform(-1, 1));
    const double k = random.uniform(0.5, 50.0), l0 = random.uniform(0.0, 3.0);
    // Body–body, body–world, world–body (both ends on one body: see the next test).
    const std::array<std::pair<int, int>, 3> ends = {{{0, 2}, {1, -1}, {-1, 2}}};
    for (const auto& [i, j] : ends) {
      const RigidBodySpringForce spring(i, pi, j, pj, k, l0);
      check_force_everywhere(spring, 3, state.q, state.v, model.mass,
                             {"rigidbodyspring", "random",
                              "seed " + std::to_string(seed) + " ends " + std::to_string(i) + " " +
                                  std::to_string(j)});
    }
  }
}

TEST(RigidBodySpringForceTest, BothEndsOnOneBodyExertNothing) {
  // A rotation does not change the distance between two points of one body: no net force, no
  // torque ((R p_i − R p_j) × f = −d × f = 0), and a constant energy.
  Random random(31);
  auto [model, state] = make_rigid_model(random_bodies(random, 2));
  randomize(random, state.q, state.v);
  const RigidBodySpringForce spring(1, Vec2(0.3, -0.7), 1, Vec2(-0.5, 0.2), 20.0, 0.4);
  const Vector g = gradient_of(spring, state.q, state.v, model.mass);
  EXPECT_LT(g.norm(), 1e-13);
  const double energy = energy_of(spring, state.q, state.v, model.mass);
  state.q[5] += 1.0;
  state.q[3] -= 2.0;
  EXPECT_NEAR(energy_of(spring, state.q, state.v, model.mass), energy, 1e-13);
}

TEST(RigidBodyWindForceTest, StickGetsTheWindTwice) {
  // A stick (−1, 0)–(1, 0) at rest, wind w = (0, 1), β = 1, P = 2: each of its two edges
  // (there and back, L = 2) pushes β (1/P) L (w·n) n = (0, 1) at each of 2 samples:
  // F = (0, 4); the samples at x = ±0.5 balance: τ = 0.
  auto [model, state] = make_rigid_model({{{{-1, 0}, {1, 0}}, {1, 1}}});
  const RigidBodyWindForce wind(model.rigid_bodies, 1.0, Vec2(0, 1), 2);
  const Vector g = gradient_of(wind, state.q, state.v, model.mass);
  EXPECT_NEAR(-g[0], 0.0, 1e-15);
  EXPECT_NEAR(-g[1], 4.0, 1e-15);
  EXPECT_NEAR(-g[2], 0.0, 1e-15);
  EXPECT_EQ(energy_of(wind, state.q, state.v, model.mass), 0.0);
}

TEST(RigidBodyWindForceTest, SpinningSquareInStillAirIsDamped) {
  // A square spinning at ω in still air: every sample's relative normal velocity opposes the
  // spin, so τ < 0 for ω > 0, and by symmetry F = 0.
  auto [model, state] = make_rigid_model({{{{-1, 1}, {1, 1}, {1, -1}, {-1, -1}}, {1, 1, 1, 1}}});
  state.v[2] = 1.5;
  const RigidBodyWindForce wind(model.rigid_bodies, 0.7, Vec2(0, 0), 5);
  const Vector g = gradient_of(wind, state.q, state.v, model.mass);
  EXPECT_NEAR(g[0], 0.0, 1e-14);
  EXPECT_NEAR(g[1], 0.0, 1e-14);
  EXPECT_GT(g[2], 0.0);
  // Still air: the normal velocity of a sample at (1, y) is ω·1 along the tangent... only the
  // normal part counts: for the edge x = 1 the normal is ±x̂, v·x̂ = −ω y. Σ over y samples of
  // β/P·L·(ω y)·y·... gives τ = −β ω Σ_edges L/P Σ_j y_j² = −0.7·1.5·4·(2/5)·Σ y_j².
  double sum = 0.0;
  for (int j = 0; j < 5; ++j) {
    const double y = -1.0 + (j + 0.5) * 2.0 / 5.0;
    sum += y * y;
  }
  EXPECT_NEAR(-g[2], -0.7 * 1.5 * 4 * (2.0 / 5.0) * sum, 1e-13);
}

TEST(RigidBodyWindForceTest, VelocityDerivativesOnRandomConfigurations) {
  for (unsigned seed = 21; seed <= 24; ++seed) {
    Random random(seed);
    auto [model, state] = make_rigid_model(random_bodies(random, 3));
    randomize(random, state.q, state.v);
    const RigidBodyWindForce wind(model.rigid_bodies, random.uniform(0.1, 3.0),
                                  Vec2(random.uniform(-2, 2), random.uniform(-2, 2)), 2 + seed % 3);
    check_force_everywhere(wind, 3, state.q, state.v, model.mass,
                           {"rigidbodywind", "random", "seed " + std::to_string(seed)});
  }
}

}  // namespace
}  // namespace fosssim::testing
