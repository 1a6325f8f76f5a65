// Tests common to every integrator (core/integrators/integrator.h), in 2D and 3D.
//
// Checked:
// - make_integrator builds the method named by the model;
// - a fixed particle with a non-zero velocity, pulled by a spring and gravity and dragged, gets
//   no force (SPEC 4): its velocity stays exactly u and it moves in a straight line,
//   x₀ + n h u after n steps, with every method; a fixed particle at rest stays exactly put;
// - step and time bookkeeping: after n steps, step = n and time = n h.

#include "core/integrators/integrator.h"

#include <gtest/gtest.h>

#include "core/integrators/explicit_euler.h"
#include "core/integrators/implicit_euler.h"
#include "core/integrators/linearized_implicit_euler.h"
#include "core/integrators/symplectic_euler.h"
#include "test_support.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(IntegratorTest);

TEST(MakeIntegrator, BuildsTheNamedMethod) {
  SceneModel model;
  model.integrator.kind = IntegratorKind::kExplicitEuler;
  EXPECT_NE(dynamic_cast<ExplicitEuler*>(make_integrator(model).get()), nullptr);
  model.integrator.kind = IntegratorKind::kSymplecticEuler;
  EXPECT_NE(dynamic_cast<SymplecticEuler*>(make_integrator(model).get()), nullptr);
  model.integrator.kind = IntegratorKind::kLinearizedImplicitEuler;
  EXPECT_NE(dynamic_cast<LinearizedImplicitEuler*>(make_integrator(model).get()), nullptr);
  model.integrator.kind = IntegratorKind::kImplicitEuler;
  EXPECT_NE(dynamic_cast<ImplicitEuler*>(make_integrator(model).get()), nullptr);
}

TYPED_TEST(IntegratorTest, FixedParticlesGetNoForceAndMoveInAStraightLine) {
  constexpr int D = TypeParam::value;
  Random random(171);
  const Vector start = random.uniform_vector(D, -1.0, 1.0);
  const Vector u = random.uniform_vector(D, -1.0, 1.0);
  const Vector anchor = random.uniform_vector(D, -1.0, 1.0);
  for (IntegratorKind kind : kAllIntegrators) {
    SCOPED_TRACE(integrator_name(kind));
    const double h = 0.01;
    TestScene scene(D, kind, h);
    scene.add_particle(2.0, start, u, /*fixed=*/true);
    scene.add_particle(1.0, start + random.unit_vector(D), random.uniform_vector(D, -1.0, 1.0));
    scene.add_particle(3.0, anchor, Vector::Zero(D), /*fixed=*/true);
    scene.add_spring(0, 1, 50.0, 0.5, 0.2);
    scene.add_spring(1, 2, 30.0, 0.8);
    scene.add_simple_gravity(random.uniform_vector(D, -10.0, 10.0));
    scene.add_drag(0.3);
    const State end = run_steps(scene.model, scene.state, 100);
    EXPECT_EQ(end.step, 100);
    EXPECT_DOUBLE_EQ(end.time, 100 * h);
    EXPECT_EQ(Vector(end.v.head(D)), u);
    expect_close(end.q.head(D), start + 100 * h * u, 1e-13, "moving fixed particle");
    EXPECT_EQ(Vector(end.q.tail(D)), anchor);
    EXPECT_TRUE(end.v.tail(D).isZero(0.0));
    EXPECT_GT((end.q.segment(D, D) - scene.state.q.segment(D, D)).norm(), 1e-3) << "free one moved";
  }
}

}  // namespace
}  // namespace fosssim::testing
