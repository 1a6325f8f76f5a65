#include "fuzz_support.h"

#include <algorithm>

#include "core/error.h"
#include "core/step/simulation.h"
#include "scripting/step_hooks.h"

namespace fosssim::fuzzing {

namespace {
/// The most iterations of any iterative part of a step (Newton, local/global, hybrid's passes).
constexpr int kMaxIterations = 20;
}  // namespace

Limits fuzz_limits() {
  Limits limits;
  limits.max_particles = 300;
  limits.max_polygon_corners = 300;  // an <elasticbody> polygon's work is quadratic in them
  limits.max_file_bytes = std::int64_t{1} << 20;
  return limits;
}

void run_a_few_steps(Scene& scene, int max_steps) {
  try {
    check_step_count(scene.model, Limits{});
    // Iteration counts are the user's to choose (up to a million Newton or local/global
    // iterations a step): a fuzzer that found them would spend seconds on one input. They are
    // capped here, so that every input costs about the same.
    SceneModel& model = scene.model;
    for (const char* name : {"newton-max-iterations", "iterations"}) {
      if (model.integrator.options.has(name) &&
          model.integrator.options.integer(name) > kMaxIterations) {
        model.integrator.options.set(name, kMaxIterations);
      }
    }
    model.collisions.max_iterations = std::min(model.collisions.max_iterations, kMaxIterations);
    Simulation simulation(model, scene.initial, scripted_additions(scene));
    for (int k = 0; k < max_steps && !simulation.finished(); ++k) simulation.step();
  } catch (const Error&) {
    // A scene that cannot run (a step that fails, a count over a limit) is reported to the
    // user with a message; only other failures are findings.
  }
}

}  // namespace fosssim::fuzzing
