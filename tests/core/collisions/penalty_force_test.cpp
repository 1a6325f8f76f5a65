// The penalty force: hand-computed forces, finite differences of its gradient and its optional
// exact Jacobian, and stiff contact under implicit integrators with and without that Jacobian.

#include "core/collisions/penalty_force.h"

#include <gtest/gtest.h>

#include "core/analysis/derivative_check.h"
#include "core/force_evaluation.h"
#include "core/force_set.h"
#include "core/step/simulation.h"
#include "core/step_error.h"
#include "support/closed_forms.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

using testing::Random;
using testing::TestScene;
using testing::vec;

/// Particle 0 overlapping particle 1, edge (2, 3) and the half-plane y ≤ 0 (normal (0, 3)).
TestScene contact_scene(PenaltyJacobian jacobian) {
  TestScene scene(2);
  scene.add_particle(1, vec({0.0, 0.15}), vec({0, 0}), false, 0.2);
  scene.add_particle(2, vec({0.32, 0.17}), vec({0, 0}), false, 0.1);
  scene.add_particle(1, vec({-1.0, 0.5}), vec({0, 0}), false, 0.05);
  scene.add_particle(1, vec({1.0, 0.4}), vec({0, 0}), false, 0.05);
  scene.add_edge(2, 3, 0.1);
  scene.add_half_plane(vec({0, 0}), vec({0, 3}));
  scene.model.collisions.method = &contact_method("penalty");
  scene.model.collisions.stiffness = 100.0;
  scene.model.collisions.thickness = 0.05;
  scene.model.collisions.penalty_jacobian = jacobian;
  return scene;
}

TEST(PenaltyForce, ForcesMatchHandComputation) {
  TestScene scene = contact_scene(PenaltyJacobian::kNone);
  const double k = 100.0, T = 0.05;
  const Vector F = compute_force(ForceSet(scene.model), scene.initial.q, scene.initial.v);
  // The hand computation in fixed-size 2-vectors: with heap vectors of a size GCC could see,
  // it warned of reads past their end in Eigen's two-double loads of dot products (a false
  // positive).
  using V2 = Eigen::Vector2d;
  // Particle-particle: n = x1 - x0 = (0.32, 0.02), δ = ‖n‖ - 0.3 - T.
  const V2 n01 = V2(0.32, 0.17) - V2(0.0, 0.15);
  const double d01 = n01.norm() - 0.3 - T;
  const V2 f01 = k * d01 * n01 / n01.norm();
  // Particle-edge: the edge from (-1, 0.5) to (1, 0.4); α = ((x0 - xa)·e)/‖e‖².
  const V2 xa(-1.0, 0.5), e(2.0, -0.1), x0(0.0, 0.15);
  const double alpha = (x0 - xa).dot(e) / e.squaredNorm();
  const V2 n0e = xa + alpha * e - x0;
  const double d0e = n0e.norm() - 0.3 - T;
  const V2 f0e = k * d0e * n0e / n0e.norm();
  // Particle-half-plane: n = (0, -0.15), δ = 0.15 - 0.2 - T; particle 1 (y = 0.17, r 0.1) is
  // out of reach of the half-plane and of the edge.
  const V2 fh = k * (0.15 - 0.2 - T) * V2(0, -1);
  testing::expect_close(F.segment(0, 2), Vector(f01 + f0e + fh), 1e-13, "particle 0");
  testing::expect_close(F.segment(2, 2), Vector(-f01), 1e-13, "particle 1");
  testing::expect_close(F.segment(4, 2), Vector(-(1.0 - alpha) * f0e), 1e-13, "edge end a");
  testing::expect_close(F.segment(6, 2), Vector(-alpha * f0e), 1e-13, "edge end b");
  // Every force pushes particle 0 out: up, away from particle 1 and down from the edge.
  EXPECT_LT(F[0], 0.0);
}

TEST(PenaltyForce, NothingOutsideRadiiPlusThicknessAndNoForceAtTheBoundary) {
  TestScene scene(2);
  scene.add_particle(1, vec({0, 0}), vec({0, 0}), false, 0.2);
  scene.add_particle(1, vec({0.5, 0}), vec({0, 0}), false, 0.25);  // 0.5 = 0.2 + 0.25 + 0.05
  scene.model.collisions.method = &contact_method("penalty");
  scene.model.collisions.thickness = 0.05;
  const Vector F = compute_force(ForceSet(scene.model), scene.initial.q, scene.initial.v);
  EXPECT_EQ(F.norm(), 0.0);
}

TEST(PenaltyForce, CourseSemanticsHaveNoJacobianAndTheGradientMatchesTheEnergy) {
  TestScene scene = contact_scene(PenaltyJacobian::kNone);
  ForceSet forces(scene.model);
  const Force& penalty = *forces.forces().back();
  EXPECT_FALSE(penalty.has_jacobian());
  HessianBuilder hessian;
  penalty.add_hessian_x(ForceInput{scene.initial.q, scene.initial.v, scene.model.mass}, hessian);
  EXPECT_TRUE(hessian.triplets().empty());
  DerivativeCheckOptions options;
  options.step = 1e-6;
  for (const DerivativeCheck& check :
       check_force_derivatives(penalty, scene.initial.q, scene.initial.v, scene.model.mass, options)) {
    EXPECT_NE(check.which, Derivative::kHessianX);
    EXPECT_TRUE(check.passed()) << derivative_name(check.which) << " " << check.relative_error();
  }
}

TEST(PenaltyForce, ExactJacobianMatchesFiniteDifferencesOnRandomContacts) {
  Random random(3);
  for (int trial = 0; trial < 20; ++trial) {
    TestScene scene(2);
    // A particle near the middle of an edge, another particle and a tilted half-plane, all
    // within reach but not at the boundary of the support.
    scene.add_particle(1, vec({random.uniform(-0.2, 0.2), random.uniform(0.05, 0.1)}), vec({0, 0}),
                       false, 0.2);
    scene.add_particle(1, vec({random.uniform(0.15, 0.25), random.uniform(0.1, 0.2)}), vec({0, 0}),
                       false, 0.1);
    scene.add_particle(1, vec({-1, random.uniform(-0.05, 0.05)}), vec({0, 0}), false, 0.05);
    scene.add_particle(1, vec({1, random.uniform(-0.05, 0.05)}), vec({0, 0}), false, 0.05);
    scene.add_edge(2, 3, 0.1);
    scene.add_half_plane(vec({0, -0.1}), random.unit_vector(2) + vec({0, 3}));
    scene.model.collisions.method = &contact_method("penalty");
    scene.model.collisions.thickness = 0.05;
    scene.model.collisions.penalty_jacobian = PenaltyJacobian::kExact;
    ForceSet forces(scene.model);
    const Force& penalty = *forces.forces().back();
    ASSERT_TRUE(penalty.has_jacobian());
    EXPECT_TRUE(
        testing::check_force_everywhere(penalty, 2, scene.initial.q, scene.initial.v, scene.model.mass,
                                        {"penalty(exact)", "random", std::to_string(trial)}));
  }
}

/// A ball of mass 0.1 falling onto a stiff floor: k = 1e5, h = 0.01, so h²k/m = 1000.
TestScene stiff_floor(std::string_view integrator, PenaltyJacobian jacobian) {
  TestScene scene(2, integrator, 0.01);
  scene.add_particle(0.1, vec({0, 0.12}), vec({0, -1}), false, 0.1);
  scene.add_simple_gravity(vec({0, -9.81}));
  scene.add_half_plane(vec({0, 0}), vec({0, 1}));
  scene.model.collisions.method = &contact_method("penalty");
  scene.model.collisions.stiffness = 1e5;
  scene.model.collisions.thickness = 0.0;
  scene.model.collisions.penalty_jacobian = jacobian;
  return scene;
}

/// Runs 200 steps; returns the largest speed reached, or infinity if the run failed.
double largest_speed(TestScene scene) {
  Simulation simulation(scene.model, scene.initial);
  double fastest = 0.0;
  try {
    for (int k = 0; k < 200; ++k) {
      simulation.step();
      fastest = std::max(fastest, simulation.state().v.norm());
    }
  } catch (const StepError&) {
    return std::numeric_limits<double>::infinity();
  }
  return fastest;
}

TEST(PenaltyForce, StiffContactIsStableUnderImplicitEulerOnlyWithTheExactJacobian) {
  for (const char* integrator : {"linearized-implicit-euler", "implicit-euler"}) {
    // The course's semantics leave the penalty force explicit: the ball, which hits the floor
    // at about 1.4 m/s, is shot back at more than ten times that speed (or Newton fails).
    EXPECT_GT(largest_speed(stiff_floor(integrator, PenaltyJacobian::kNone)), 14.0) << integrator;
    // With its Jacobian the contact is implicit too: the ball settles, never faster than it fell.
    EXPECT_LT(largest_speed(stiff_floor(integrator, PenaltyJacobian::kExact)), 1.5) << integrator;
  }
}

TEST(PenaltyForce, WorkedExampleE2HalfPlaneForceIsTheCoursesToTheLastBit) {
  // The course's program: the force re-projected onto the scene's N, -N ((n̂·N) s ÷ (N·N)),
  // gives these bits after one symplectic step; k δ n̂ with n̂ = n ÷ l gives
  // v = (182.84271247461899, ...), x = (181.892712474619, 181.992712474619).
  TestScene scene(2, "symplectic-euler", 1.0);
  scene.add_particle(1, vec({-0.95, -0.85}), vec({0, 0}), false, 0.2);
  scene.add_half_plane(vec({-1, -1}), vec({1, 1}));
  scene.model.collisions.method = &contact_method("penalty");
  scene.model.collisions.stiffness = 1000.0;
  scene.model.collisions.thickness = 0.2;
  const State next = testing::run_steps(scene.model, scene.initial, 1);
  EXPECT_EQ(next.v[0], 182.84271247461902);
  EXPECT_EQ(next.v[1], 182.84271247461902);
  EXPECT_EQ(next.q[0], 181.89271247461903);
  EXPECT_EQ(next.q[1], 181.99271247461903);
}

}  // namespace
}  // namespace fosssim
