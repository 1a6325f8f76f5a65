// Hand-computed single steps of SymplecticEuler (docs/integrators.md, 'Symplectic Euler') in 2D and
// 3D.
//
// Math checked, with h the time step and F./m the acceleration:
// - a particle under gravity g: vⁿ⁺¹ = vⁿ + h g, then qⁿ⁺¹ = qⁿ + h vⁿ⁺¹ (the NEW velocity),
//   so qⁿ⁺¹ = qⁿ + h vⁿ + h² g;
// - a spring (k, l0, damping b) from a fixed particle at a moving with velocity u to a free
//   particle at x with velocity w, plus drag c: the fixed particle gets no force and moves
//   straight on, a + h u, with velocity u; the free one gets
//   vⁿ⁺¹ = w + (h/m)(F_spring(a, x, u, w) - c w) with F from the OLD state, written out from
//   docs/forces.md in the test, and qⁿ⁺¹ = x + h vⁿ⁺¹;
// - step and time bookkeeping: step = 1, time = h after one step.

#include "core/integrators/symplectic_euler.h"

#include <gtest/gtest.h>

#include "support/closed_forms.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(SymplecticEulerTest);

TYPED_TEST(SymplecticEulerTest, ParticleUnderGravityMovesWithTheNewVelocity) {
  constexpr int D = TypeParam::value;
  const double h = 0.1;
  const FallingParticle p(D, 111);
  const TestScene scene = p.scene("symplectic-euler", h);
  const State next = run_steps(scene.model, scene.initial, 1);
  expect_close(next.q, p.x + h * p.w + h * h * p.g, 1e-15, "position");
  expect_close(next.v, p.w + h * p.g, 1e-15, "velocity");
  EXPECT_EQ(next.step, 1);
  EXPECT_EQ(next.time, h);
}

TYPED_TEST(SymplecticEulerTest, SpringFromAMovingFixedParticle) {
  constexpr int D = TypeParam::value;
  const double h = 0.05;
  const AnchoredSpring s(D, 112, 1.5, 40.0, 0.7, 0.9, 0.3);
  const TestScene scene = s.scene("symplectic-euler", h);
  const State next = run_steps(scene.model, scene.initial, 1);
  const Vector force = spring_force_on_j(s.a, s.x, s.u, s.w, s.k, s.l0, s.b) - s.c * s.w;
  const Vector velocity = s.w + (h / s.m) * force;
  s.expect_step(next, h, s.x + h * velocity, velocity, 1e-14);
}

}  // namespace
}  // namespace fosssim::testing
