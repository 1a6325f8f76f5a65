// The local/global solver on cloth: convergence to Newton's implicit Euler and settling.

#include <gtest/gtest.h>

#include "core/force_evaluation.h"
#include "core/forces/drag_damping_force.h"
#include "core/integrators/implicit_euler.h"
#include "core/integrators/local_global.h"
#include "core/step/simulation.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

TEST(LocalGlobalCloth, ConvergesToNewtonsImplicitEulerAsIterationsGrow) {
  Scene scene = testing::cloth(7, 20.0, "local-global", 1.0 / 30.0);
  const State start = testing::moving_cloth_state();

  State newton_state = start;
  ImplicitEuler newton(NewtonSettings{1e-13, 200});
  newton.precompute(scene.model);
  newton.step(newton_state);

  std::vector<double> errors;
  for (int iterations = 1; iterations <= 4096; iterations *= 2) {
    LocalGlobalSettings settings;
    settings.iterations = iterations;
    LocalGlobal<3> local_global(settings);
    local_global.precompute(scene.model);
    State state = start;
    local_global.step(state);
    errors.push_back((state.q - newton_state.q).lpNorm<Eigen::Infinity>());
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    EXPECT_LE(errors[k], 1.05 * errors[k - 1])
        << "error grew from " << (1 << (k - 1)) << " to " << (1 << k) << " iterations";
  }
  EXPECT_GT(errors.front(), 1e-3) << "one iteration is far from the solution";
  EXPECT_LT(errors[8], 0.01 * errors.front()) << "256 iterations gain a factor 100";
  EXPECT_LT(errors.back(), 1e-12) << "4096 iterations reach it";
}

/// Runs a cloth held at two corners, in air drag (taken explicitly by the local/global
/// solver), for `steps` and returns (max speed, max net force on a free vertex
/// relative to its weight) at the end.
std::pair<double, double> settle(std::string_view kind, int steps) {
  Scene scene = testing::cloth(6, 40.0, kind, 1.0 / 30.0, true, "corners");
  scene.model.forces.push_back(std::make_unique<DragDampingForce<3>>(0.005));  // air drag
  if (scene.model.integrator.options.has("iterations")) {
    scene.model.integrator.options.set("iterations", 40);
  }
  Simulation simulation(scene.model, scene.initial);
  for (int step = 0; step < steps; ++step) simulation.step();
  const State& state = simulation.state();
  Vector force = compute_force(ForceSet(scene.model), state.q, Vector::Zero(state.v.size()));
  zero_fixed(scene.model, force);
  const double weight = scene.model.mass[0] * 9.8;
  return {state.v.lpNorm<Eigen::Infinity>(), force.lpNorm<Eigen::Infinity>() / weight};
}

TEST(LocalGlobalCloth, AHangingClothSettlesToRest) {
  for (std::string_view kind : {"local-global", "linearly-implicit-euler"}) {
    const auto [early_speed, early_force] = settle(kind, 15);
    // Half a minute of simulated time; the local/global solver's unconverged iterations make
    // the last millimetres creep, so it needs about that long.
    const auto [speed, force] = settle(kind, 900);
    EXPECT_GT(early_speed, 0.1) << std::string(kind);
    EXPECT_LT(speed, 1e-5) << std::string(kind);
    EXPECT_LT(force, 1e-3) << std::string(kind) << ": not in static equilibrium";
  }
}

}  // namespace
}  // namespace fosssim
