// Hand-computed single steps of LinearizedImplicitEuler (docs/integrators.md, 'Linearized implicit
// Euler') in 2D and 3D.
//
// Math checked. The step evaluates at the predicted state q* = qⁿ + h vⁿ, solves
// (M + h² hessX + h hessV) δv = h F(q*, vⁿ) with fixed particles eliminated, and sets
// vⁿ⁺¹ = vⁿ + δv, qⁿ⁺¹ = qⁿ + h vⁿ⁺¹.
// - A particle under gravity: no Hessians, δv = h g; so qⁿ⁺¹ = qⁿ + h vⁿ + h² g.
// - An undamped spring (k, l0) from a fixed particle (at a, velocity u) to a free one (x, w),
//   plus drag c. With d = (x + h w) - (a + h u), l = |d|, n = d/l, P = n nᵀ, the free block of A is
//   (m + h c) I + h² k [P + ((l - l0)/l)(I - P)], whose eigenvectors are n (eigenvalue
//   m + h c + h² k) and the plane ⊥ n (m + h c + h² k (l - l0)/l); so with rhs = h F_1,
//   δv = (rhs·n) n / (m + h c + h² k) + (rhs - (rhs·n) n) / (m + h c + h² k (l - l0)/l).
// - The same with internal damping b > 0: the free block
//   (m + h c) I + h² (k [P + ((l-l0)/l)(I - P)] + (b/l)[n dvᵀ + (n·dv) I](I - P)) + h b P
//   written out from docs/forces.md and solved densely in the test (the non-symmetric, LU path).
// - Linear systems (zero-rest-length spring + drag), where the method is backward Euler and
//   the step has the closed forms of support/closed_forms.h: to 1e-14, with a moving fixed particle
//   and with two free particles.

#include "core/integrators/linearized_implicit_euler.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "support/closed_forms.h"
#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(LinearizedImplicitEulerTest);

constexpr std::string_view kLinearizedKind = "linearized-implicit-euler";

TYPED_TEST(LinearizedImplicitEulerTest, ParticleUnderGravity) {
  constexpr int D = TypeParam::value;
  const double h = 0.1;
  const FallingParticle p(D, 121);
  const TestScene scene = p.scene(kLinearizedKind, h);
  const State next = run_steps(scene.model, scene.initial, 1);
  expect_close(next.v, p.w + h * p.g, 1e-15, "velocity");
  expect_close(next.q, p.x + h * p.w + h * h * p.g, 1e-15, "position");
}

TYPED_TEST(LinearizedImplicitEulerTest, UndampedSpringFromAMovingFixedParticle) {
  constexpr int D = TypeParam::value;
  const double h = 0.1;
  for (unsigned seed = 122; seed <= 124; ++seed) {
    const AnchoredSpring s(D, seed, 1.5, 200.0, 0.7, 0.0, 0.3);
    const Vector d = (s.x + h * s.w) - (s.a + h * s.u);
    const double l = d.norm();
    const Vector n = d / l;
    const Vector rhs = h * (-s.k * (l - s.l0) * n - s.c * s.w);
    const double along = rhs.dot(n);
    const Vector dv = along * n / (s.m + h * s.c + h * h * s.k) +
                      (rhs - along * n) / (s.m + h * s.c + h * h * s.k * (l - s.l0) / l);
    const TestScene scene = s.scene(kLinearizedKind, h);
    s.expect_step(run_steps(scene.model, scene.initial, 1), h, s.x + h * (s.w + dv), s.w + dv,
                  1e-14);
  }
}

TYPED_TEST(LinearizedImplicitEulerTest, DampedSpringFromAMovingFixedParticle) {
  constexpr int D = TypeParam::value;
  const double h = 0.1;
  for (unsigned seed = 125; seed <= 127; ++seed) {
    const AnchoredSpring s(D, seed, 1.5, 200.0, 0.7, 2.5, 0.3);
    const Vector d = (s.x + h * s.w) - (s.a + h * s.u);
    const Vector rel = s.w - s.u;
    const double l = d.norm();
    const Vector n = d / l;
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(D, D);
    const Eigen::MatrixXd P = n * n.transpose();
    const Eigen::MatrixXd hess_x = s.k * (P + ((l - s.l0) / l) * (I - P)) +
                                   (s.b / l) * (n * rel.transpose() + n.dot(rel) * I) * (I - P);
    const Eigen::MatrixXd A = (s.m + h * s.c) * I + h * h * hess_x + h * s.b * P;
    const Vector rhs = h * (-s.k * (l - s.l0) * n - s.b * n.dot(rel) * n - s.c * s.w);
    const Vector dv = A.partialPivLu().solve(rhs);
    const TestScene scene = s.scene(kLinearizedKind, h);
    s.expect_step(run_steps(scene.model, scene.initial, 1), h, s.x + h * (s.w + dv), s.w + dv,
                  1e-14);
  }
}

TYPED_TEST(LinearizedImplicitEulerTest, LinearSystemsStepInClosedForm) {
  constexpr int D = TypeParam::value;
  Random random(128);
  const auto r = [&] { return random.uniform_vector(D, -1.0, 1.0); };
  const LinearAnchoredSystem anchored{0.2, 1.3, 150.0, 0.7, r(), r(), r(), r()};
  TestScene scene = anchored.scene(kLinearizedKind);
  State next = run_steps(scene.model, scene.initial, 1);
  State expected = anchored.backward_euler_step();
  expect_close(next.q, expected.q, 1e-14, "anchored: positions");
  expect_close(next.v, expected.v, 1e-14, "anchored: velocities");

  const LinearPairSystem pair{0.2, 0.8, 90.0, 0.4, r(), r(), r(), r()};
  scene = pair.scene(kLinearizedKind);
  next = run_steps(scene.model, scene.initial, 1);
  expected = pair.backward_euler_step();
  expect_close(next.q, expected.q, 1e-14, "pair: positions");
  expect_close(next.v, expected.v, 1e-14, "pair: velocities");
}

}  // namespace
}  // namespace fosssim::testing
