// The mesh integrators that solve implicit Euler iteratively (newton, quasi-newton,
// accelerated-local-global) against the course's implicit Euler converged to round-off.

#include <gtest/gtest.h>

#include "core/integrators/implicit_euler.h"
#include "core/integrators/local_global.h"
#include "core/integrators/newton.h"
#include "core/integrators/quasi_newton.h"
#include "core/step/simulation.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

constexpr double kClothDt = 1.0 / 30.0;
constexpr double kStiffness = 20.0;

/// The implicit Euler step from `start` by the course's Newton solver, to round-off.
State exact_step(const SceneModel& model, const State& start) {
  ImplicitEuler newton(NewtonSettings{1e-12, 200});
  newton.precompute(model);
  State state = start;
  newton.step(state);
  return state;
}

/// The largest distance of the positions of a step of `method` (with option `name` = `value`)
/// from the exact step, relative to how far the exact step moves the cloth.
double step_error(const std::string& method,
                  std::initializer_list<std::pair<std::string_view, double>> options) {
  Scene scene = testing::cloth(7, kStiffness, method, kClothDt);
  for (const auto& [name, value] : options) scene.model.integrator.options.set(name, value);
  const State start = testing::moving_cloth_state();
  const State exact = exact_step(scene.model, start);
  State state = start;
  std::unique_ptr<Integrator> integrator = make_integrator(scene.model);
  integrator->step(state);
  return (state.q - exact.q).lpNorm<Eigen::Infinity>() /
         (exact.q - start.q).lpNorm<Eigen::Infinity>();
}

TEST(ImplicitSolvers, NewtonReachesTheImplicitEulerStepToRoundOff) {
  EXPECT_LT(step_error("newton", {{"tolerance", 1e-12}}), 1e-10);
}

TEST(ImplicitSolvers, QuasiNewtonConvergesToTheImplicitEulerStep) {
  EXPECT_LT(step_error("quasi-newton", {{"tolerance", 1e-12}, {"iterations", 1000}}), 1e-9);
  // A few L-BFGS iterations are already far closer than as many local/global ones.
  const double quasi_newton = step_error("quasi-newton", {{"iterations", 30}, {"tolerance", 0.0}});
  const double local_global = step_error("local-global", {{"iterations", 30}});
  EXPECT_LT(quasi_newton, 0.1 * local_global);
}

TEST(ImplicitSolvers, AndersonAccelerationConvergesToTheImplicitEulerStepFarFaster) {
  // Undamped springs: converged local/global iterations solve implicit Euler exactly.
  EXPECT_LT(step_error("accelerated-local-global", {{"iterations", 400}}), 1e-10);
  const double accelerated = step_error("accelerated-local-global", {{"iterations", 30}});
  const double plain = step_error("local-global", {{"iterations", 30}});
  EXPECT_LT(accelerated, 0.05 * plain);
  EXPECT_GT(plain, 1e-2) << "30 plain iterations are visibly unconverged";
  EXPECT_LT(step_error("accelerated-local-global", {{"iterations", 100}}), 1e-7);
  EXPECT_GT(step_error("local-global", {{"iterations", 100}}), 1e-3);
}

TEST(ImplicitSolvers, ChebyshevAccelerationConvergesToTheImplicitEulerStep) {
  Scene scene = testing::cloth(7, kStiffness, "accelerated-local-global", kClothDt);
  scene.model.integrator.options.set("acceleration", std::string("chebyshev"));
  scene.model.integrator.options.set("rho", 0.98);
  scene.model.integrator.options.set("iterations", 400);
  const State start = testing::moving_cloth_state();
  const State exact = exact_step(scene.model, start);
  State state = start;
  make_integrator(scene.model)->step(state);
  EXPECT_LT((state.q - exact.q).lpNorm<Eigen::Infinity>(), 1e-10);
}

}  // namespace
}  // namespace fosssim
