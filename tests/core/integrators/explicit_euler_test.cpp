// Hand-computed single steps of ExplicitEuler (docs/integrators.md, 'Explicit Euler') in 2D and 3D.
//
// Math checked, with h the time step and F./m the acceleration:
// - a particle under gravity g: qⁿ⁺¹ = qⁿ + h vⁿ (the OLD velocity), vⁿ⁺¹ = vⁿ + h g;
// - a spring (k, l0, damping b) from a fixed particle at a moving with velocity u to a free
//   particle at x with velocity w, plus drag c: the fixed particle gets no force and moves
//   straight on, a + h u, with velocity u; the free one gets qⁿ⁺¹ = x + h w and
//   vⁿ⁺¹ = w + (h/m)(F_spring(a, x, u, w) - c w), F written out from docs/forces.md in the test;
// - step and time bookkeeping: step = 1, time = h after one step.

#include "core/integrators/explicit_euler.h"

#include <gtest/gtest.h>

#include "support/closed_forms.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ExplicitEulerTest);

TYPED_TEST(ExplicitEulerTest, ParticleUnderGravityMovesWithTheOldVelocity) {
  constexpr int D = TypeParam::value;
  const double h = 0.1;
  const FallingParticle p(D, 101);
  const TestScene scene = p.scene("explicit-euler", h);
  const State next = run_steps(scene.model, scene.initial, 1);
  expect_close(next.q, p.x + h * p.w, 1e-15, "position");
  expect_close(next.v, p.w + h * p.g, 1e-15, "velocity");
  EXPECT_EQ(next.step, 1);
  EXPECT_EQ(next.time, h);
}

TYPED_TEST(ExplicitEulerTest, SpringFromAMovingFixedParticle) {
  constexpr int D = TypeParam::value;
  const double h = 0.05;
  const AnchoredSpring s(D, 102, 1.5, 40.0, 0.7, 0.9, 0.3);
  const TestScene scene = s.scene("explicit-euler", h);
  const State next = run_steps(scene.model, scene.initial, 1);
  const Vector force = spring_force_on_j(s.a, s.x, s.u, s.w, s.k, s.l0, s.b) - s.c * s.w;
  s.expect_step(next, h, s.x + h * s.w, s.w + (h / s.m) * force, 1e-14);
}

}  // namespace
}  // namespace fosssim::testing
