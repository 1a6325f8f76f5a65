// Tests of backward Euler's equations in the velocity change (core/systems/backward_euler.h),
// in 2D and 3D.
//
// Math checked:
// - the residual r(dv) = h F(qⁿ + h(vⁿ + dv), vⁿ + dv) - M dv vanishes (to Newton's tolerance)
//   at the step ImplicitEuler takes, and is zero on fixed DOFs;
// - for conservative forces -r is the gradient of the incremental potential
//   Φ(dv) = ½ dvᵀM dv + U(qⁿ + h(vⁿ + dv)) on the free DOFs: central differences of Φ agree
//   to 1e-7 relative;
// - potential_line_search returns a step that decreases Φ by Armijo's rule, also when handed a
//   direction that climbs (it then descends along M⁻¹ r), and reports Φ there and the fraction
//   of the direction it took; residual_line_search decreases ‖r‖.

#include "core/systems/backward_euler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(BackwardEulerTest);

/// A stretched chain hanging from a fixed particle, under gravity: conservative.
template <int D>
TestScene spring_chain(double h) {
  Random random(301);
  TestScene scene(D, "implicit-euler", h);
  scene.add_particle(1.0, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
  for (int p = 1; p < 4; ++p) {
    scene.add_particle(random.uniform(0.5, 2.0), random.uniform_vector(D, -1.0, 1.0) * 1.5,
                       random.uniform_vector(D, -1.0, 1.0));
    scene.add_spring(p - 1, p, 60.0, 0.5);
  }
  Vector g = Vector::Zero(D);
  g[1] = -9.81;
  scene.add_simple_gravity(g);
  return scene;
}

TYPED_TEST(BackwardEulerTest, TheResidualVanishesAtImplicitEulersStep) {
  constexpr int D = TypeParam::value;
  const TestScene scene = spring_chain<D>(0.05);
  const ForceSet forces(scene.model);
  const BackwardEulerStep problem{forces, scene.initial, 0.05};
  State next = scene.initial;
  make_integrator(scene.model)->step(next);
  const Vector dv = next.v - scene.initial.v;
  const Vector r = problem.residual(dv);
  const Vector r0 = problem.residual(Vector::Zero(dv.size()));
  EXPECT_LE(r.norm(), 1e-8 * r0.norm()) << "Newton stops at a correction below 1e-9";
  EXPECT_EQ(Vector(r0.head(D)), Vector::Zero(D)) << "fixed DOFs are zeroed";
}

TYPED_TEST(BackwardEulerTest, MinusTheResidualIsTheGradientOfTheIncrementalPotential) {
  constexpr int D = TypeParam::value;
  const TestScene scene = spring_chain<D>(0.05);
  const ForceSet forces(scene.model);
  const BackwardEulerStep problem{forces, scene.initial, 0.05};
  Random random(302);
  const Vector dv = random.uniform_vector(scene.model.num_dofs(), -0.5, 0.5);
  const Vector gradient = -problem.residual(dv);
  const double t = 1e-6;
  for (int k = D; k < scene.model.num_dofs(); ++k) {  // the free DOFs
    Vector plus = dv, minus = dv;
    plus[k] += t;
    minus[k] -= t;
    const double numeric =
        (problem.incremental_potential(plus) - problem.incremental_potential(minus)) /
        (plus[k] - minus[k]);
    EXPECT_NEAR(numeric, gradient[k], 1e-7 * (1.0 + gradient.norm())) << "DOF " << k;
  }
}

TYPED_TEST(BackwardEulerTest, LineSearchesDecreaseTheirMerit) {
  constexpr int D = TypeParam::value;
  const TestScene scene = spring_chain<D>(0.2);  // a large step: the full Newton step may overshoot
  const ForceSet forces(scene.model);
  const BackwardEulerStep problem{forces, scene.initial, 0.2};
  const Vector dv = Vector::Zero(scene.model.num_dofs());
  const Vector r = problem.residual(dv);
  const double phi = problem.incremental_potential(dv);
  // Along the residual itself (a descent direction for Φ, since -r is its gradient).
  double potential = std::numeric_limits<double>::quiet_NaN();
  double fraction = 0.0;
  const Vector step = potential_line_search(problem, dv, r, r, &potential, &fraction);
  EXPECT_LT(problem.incremental_potential(dv + step), phi + 1e-4 * (-r.dot(step)));
  // It reports Φ at the end and the fraction of the direction taken: a power of 1/2.
  EXPECT_EQ(potential, problem.incremental_potential(dv + step));
  EXPECT_GT(fraction, 0.0);
  EXPECT_LE(fraction, 1.0);
  EXPECT_EQ(std::exp2(std::round(std::log2(fraction))), fraction);
  EXPECT_TRUE(step == fraction * r);
  // Along a climbing direction: it turns to M⁻¹ r and still descends.
  const Vector climb = potential_line_search(problem, dv, r, -r);
  EXPECT_LT(problem.incremental_potential(dv + climb), phi);
  EXPECT_GT(climb.dot(r), 0.0);
  // The residual's own search along r, whose merit ½‖r‖² must fall.
  Vector rhs = r;
  const Vector rstep = residual_line_search(problem, dv, rhs, r.cwiseQuotient(forces.mass()));
  EXPECT_LT(rhs.squaredNorm(), r.squaredNorm());
  EXPECT_TRUE(rhs.isApprox(problem.residual(dv + rstep), 1e-15)) << "rhs is updated";
}

}  // namespace
}  // namespace fosssim::testing
