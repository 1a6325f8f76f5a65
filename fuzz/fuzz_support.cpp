#include "fuzz_support.h"

#include "core/error.h"
#include "core/step/simulation.h"
#include "scripting/step_hooks.h"

namespace fosssim::fuzzing {

Limits fuzz_limits() {
  Limits limits;
  limits.max_particles = 300;
  limits.max_file_bytes = std::int64_t{1} << 20;
  return limits;
}

void run_a_few_steps(const Scene& scene, int max_steps) {
  try {
    check_step_count(scene.model, Limits{});
    Simulation simulation(scene.model, scene.initial, scripted_additions(scene));
    for (int k = 0; k < max_steps && !simulation.finished(); ++k) simulation.step();
  } catch (const Error&) {
    // A scene that cannot run (a step that fails, a count over a limit) is reported to the
    // user with a message; only other failures are findings.
  }
}

}  // namespace fosssim::fuzzing
