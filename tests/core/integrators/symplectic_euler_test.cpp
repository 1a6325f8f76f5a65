// Hand-computed single steps of SymplecticEuler (SPEC 4, compat order) in 2D and 3D.
//
// Math checked, with h the time step and F./m the acceleration:
// - a particle under gravity g: vⁿ⁺¹ = vⁿ + h g, then qⁿ⁺¹ = qⁿ + h vⁿ⁺¹ (the NEW velocity),
//   so qⁿ⁺¹ = qⁿ + h vⁿ + h² g;
// - a spring (k, l0, damping b) from a fixed particle at a moving with velocity u to a free
//   particle at x with velocity w, plus drag c: the fixed particle gets no force and moves
//   straight on, a + h u, with velocity u; the free one gets
//   vⁿ⁺¹ = w + (h/m)(F_spring(a, x, u, w) - c w) with F from the OLD state, written out from
//   SPEC 3.2 in the test, and qⁿ⁺¹ = x + h vⁿ⁺¹;
// - step and time bookkeeping: step = 1, time = h after one step.

#include "core/integrators/symplectic_euler.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace fosssim::testing {
namespace {

template <typename T>
class SymplecticEulerTest : public ::testing::Test {};
TYPED_TEST_SUITE(SymplecticEulerTest, Dimensions, DimensionName);

TYPED_TEST(SymplecticEulerTest, ParticleUnderGravityMovesWithTheNewVelocity) {
  constexpr int D = TypeParam::value;
  Random random(111);
  const double h = 0.1;
  const Vector x = random.uniform_vector(D, -1.0, 1.0), w = random.uniform_vector(D, -1.0, 1.0);
  const Vector g = random.uniform_vector(D, -10.0, 10.0);
  TestScene scene(D, IntegratorKind::kSymplecticEuler, h);
  scene.add_particle(2.0, x, w);
  scene.add_simple_gravity(g);
  const State next = run_steps(scene.model, scene.state, 1);
  expect_close(next.q, x + h * w + h * h * g, 1e-15, "position");
  expect_close(next.v, w + h * g, 1e-15, "velocity");
  EXPECT_EQ(next.step, 1);
  EXPECT_EQ(next.time, h);
}

TYPED_TEST(SymplecticEulerTest, SpringFromAMovingFixedParticle) {
  constexpr int D = TypeParam::value;
  Random random(112);
  const double h = 0.05, m = 1.5, k = 40.0, l0 = 0.7, b = 0.9, c = 0.3;
  const Vector a = random.uniform_vector(D, -1.0, 1.0), u = random.uniform_vector(D, -1.0, 1.0);
  const Vector x = random.uniform_vector(D, -1.0, 1.0), w = random.uniform_vector(D, -1.0, 1.0);
  TestScene scene(D, IntegratorKind::kSymplecticEuler, h);
  scene.add_particle(5.0, a, u, /*fixed=*/true);
  scene.add_particle(m, x, w);
  scene.add_spring(0, 1, k, l0, b);
  scene.add_drag(c);
  const State next = run_steps(scene.model, scene.state, 1);

  const Vector force = spring_force_on_j(a, x, u, w, k, l0, b) - c * w;
  expect_close(next.q.head(D), a + h * u, 1e-15, "fixed particle's position");
  EXPECT_EQ(Vector(next.v.head(D)), u) << "a fixed particle keeps its velocity exactly";
  const Vector velocity = w + (h / m) * force;
  expect_close(next.v.tail(D), velocity, 1e-14, "free particle's velocity");
  expect_close(next.q.tail(D), x + h * velocity, 1e-14, "free particle's position");
}

}  // namespace
}  // namespace fosssim::testing
