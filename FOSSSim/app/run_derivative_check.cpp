#include <cstdio>
#include <iostream>

#include "app/commands.h"
#include "cli/exit_codes.h"
#include "core/analysis/derivative_check.h"

namespace fosssim {

int run_derivative_check(const Scene& scene, const Options&) {
  DerivativeCheckOptions check_options;
  check_options.step = suggest_finite_difference_step(scene.initial.q, scene.model.dim);
  const auto checks =
      check_model_derivatives(scene.model, scene.initial.q, scene.initial.v, check_options);
  std::printf(
      "Finite-difference check at the initial state of %s (steps %.3g in q and %.3g\n"
      "in v, %d random directions%s; Richardson-extrapolated central differences).\n"
      "A check passes when its error is within rtol %.0e of the value plus the\n"
      "round-off floor of the differences; 'used' is the error over that allowance.\n\n",
      scene.source.c_str(), check_options.step, check_options.velocity_step,
      check_options.random_directions,
      scene.model.num_dofs() <= check_options.all_directions_up_to ? " and every unit direction"
                                                                   : "",
      check_options.relative_tolerance);
  std::printf("%-32s %-9s %11s %11s %11s %9s  %s\n", "force", "quantity", "rel. error",
              "abs. error", "floor", "used", "verdict");
  bool all_passed = true;
  for (const DerivativeCheck& check : checks) {
    // Where both sides are round-off, the relative error is noise over noise: show a dash and
    // say why in the verdict rather than "rel. error 1.000e+00 ... ok".
    char relative[16] = "          -";
    if (!check.vanishes()) std::snprintf(relative, sizeof relative, "%11.3e", check.relative_error());
    std::printf("%-32s %-9s %s %11.3e %11.3e %9.2e  %s\n", check.force.c_str(),
                derivative_name(check.which), relative, check.absolute_error, check.noise_floor,
                check.allowance_used,
                !check.passed() ? "FAILED" : (check.vanishes() ? "ok (zero)" : "ok"));
    all_passed = all_passed && check.passed();
  }
  std::printf("\n%zu checks, %s\n", checks.size(), all_passed ? "all passed" : "some FAILED");
  return all_passed ? kExitOk : kExitGradingFailed;
}

}  // namespace fosssim
