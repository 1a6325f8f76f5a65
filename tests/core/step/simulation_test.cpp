// Tests of Simulation (core/step/simulation.h): the health check after every step, and
// determinism.
//
// Checked:
// - explicit Euler on a very stiff spring with a large step (k = 1e8, m = 1, h = 0.1, so the
//   amplification per step is about h√(k/m) = 1000) blows up; every state Simulation::step
//   returns normally is finite, and the step that produces a non-finite state throws StepError
//   naming that step and the particle (the only free one), with the state left as produced;
// - check_state_is_finite names the first bad particle and whether its position or its velocity
//   is bad;
// - running the same model twice from the same state gives bit-identical states (memcmp of q
//   and v) with every integrator of the registry, on a 3D scene with all six kinds of force and
//   a fixed particle;
// - finished() after model.num_steps() steps.

#include "core/step/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/forces/constant_force.h"
#include "core/forces/vortex_force.h"
#include "core/step_error.h"
#include "support/closed_forms.h"
#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

TEST(SimulationHealthCheck, BlowUpIsReportedAtTheStepThatProducesIt) {
  TestScene scene(2, "explicit-euler", 0.1);
  scene.add_particle(1.0, vec({0.0, 0.0}), vec({0.0, 0.0}), /*fixed=*/true);
  scene.add_particle(1.0, vec({1.2, 0.1}), vec({0.0, 0.0}));
  scene.add_spring(0, 1, 1e8, 1.0);
  Simulation simulation(scene.model, scene.initial);
  std::int64_t returned_steps = 0;
  try {
    for (; returned_steps < 10000; ++returned_steps) {
      simulation.step();
      ASSERT_TRUE(simulation.state().q.allFinite() && simulation.state().v.allFinite())
          << "a non-finite state was returned silently after step " << simulation.state().step;
    }
    FAIL() << "expected the simulation to blow up";
  } catch (const StepError& error) {
    const State& state = simulation.state();
    EXPECT_EQ(error.step(), returned_steps + 1);
    EXPECT_EQ(state.step, error.step());
    EXPECT_FALSE(state.q.allFinite() && state.v.allFinite()) << "the state is the one produced";
    const std::string message = error.what();
    EXPECT_EQ(
        message.rfind("step " + std::to_string(error.step()) + ": particle 1 has a non-finite ", 0),
        0u)
        << message;
    std::printf("blew up as expected: %s\n", message.c_str());
  }
  EXPECT_GT(returned_steps, 10) << "the blow-up takes a while (growth ~1000 per step)";
}

TEST(SimulationHealthCheck, NamesTheFirstBadParticleAndQuantity) {
  SceneModel model;
  model.dim = 3;
  model.fixed = {false, false, false};
  State state;
  state.q = Vector::Zero(9);
  state.v = Vector::Zero(9);
  state.step = 7;
  EXPECT_NO_THROW(check_state_is_finite(model, state));
  state.v[7] = std::numeric_limits<double>::quiet_NaN();
  state.q[8] = std::numeric_limits<double>::infinity();
  try {
    check_state_is_finite(model, state);
    FAIL() << "expected StepError";
  } catch (const StepError& error) {
    EXPECT_EQ(error.step(), 7);
    EXPECT_EQ(std::string(error.what())
                  .rfind("step 7: particle 2 has a non-finite position (0, 0, inf)", 0),
              0u)
        << error.what();
  }
  state.q[8] = 0.0;
  try {
    check_state_is_finite(model, state);
    FAIL() << "expected StepError";
  } catch (const StepError& error) {
    EXPECT_NE(std::string(error.what()).find("particle 2 has a non-finite velocity (0, nan, 0)"),
              std::string::npos)
        << error.what();
  }
}

/// Every kind of force in 3D, with damping, a vortex and a fixed particle.
TestScene busy_scene(std::string_view kind) {
  Random random(161);
  TestScene scene(3, kind, 0.005);
  for (int p = 0; p < 6; ++p) {
    scene.add_particle(random.uniform(0.5, 2.0), random.uniform_vector(3, -1.0, 1.0),
                       random.uniform_vector(3, -1.0, 1.0), p == 0);
  }
  for (int p = 1; p < 6; ++p) scene.add_spring(p - 1, p, 50.0, 0.6, p % 2 == 0 ? 0.3 : 0.0);
  scene.add_simple_gravity(vec({0.0, -9.81, 0.0}));
  scene.add_gravitation(1, 4, 0.3);
  scene.add_force(std::make_unique<ConstantForce<3>>(Vec<3>(0.1, 0.2, -0.3)));
  scene.add_drag(0.05);
  scene.add_force(std::make_unique<VortexForce<3>>(2, 5, 0.5, 0.2,
                                                   cross_product_matrix(Vec<3>(0.0, 0.0, 1.0))));
  scene.model.duration = 1.0;
  return scene;
}

TEST(SimulationDeterminism, TwoRunsGiveIdenticalBytesWithEveryIntegrator) {
  for (const IntegratorMethod* method : all_integrators()) {
    const std::string_view kind = method->name;
    SCOPED_TRACE(std::string(kind));
    const TestScene scene = busy_scene(kind);
    ASSERT_EQ(scene.model.num_steps(), 200);
    Simulation first(scene.model, scene.initial), second(scene.model, scene.initial);
    while (!first.finished()) first.step();
    while (!second.finished()) second.step();
    const State& a = first.state();
    const State& b = second.state();
    EXPECT_EQ(a.step, 200);
    EXPECT_EQ(a.time, 200 * 0.005);
    EXPECT_NE((a.q - scene.initial.q).norm(), 0.0) << "the scene moved";
    ASSERT_EQ(a.q.size(), b.q.size());
    EXPECT_EQ(std::memcmp(a.q.data(), b.q.data(), sizeof(double) * a.q.size()), 0);
    EXPECT_EQ(std::memcmp(a.v.data(), b.v.data(), sizeof(double) * a.v.size()), 0);
  }
}

}  // namespace
}  // namespace fosssim::testing
