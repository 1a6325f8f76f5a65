#include <cstdio>
#include <iostream>

#include "app/commands.h"
#include "app/exit_codes.h"
#include "core/analysis/derivative_check.h"

namespace fosssim {

int run_derivative_check(const Scene& scene, const Options&) {
  DerivativeCheckOptions check_options;
  check_options.step = suggest_finite_difference_step(scene.initial.q, scene.model.dim);
  const auto checks = check_model_derivatives(scene.model, scene.initial.q, scene.initial.v,
                                              check_options);
  std::printf("Finite-difference check at the initial state of %s (step %.3g, %d random\n"
              "directions%s; Richardson-extrapolated central differences)\n\n",
              scene.source.c_str(), check_options.step, check_options.random_directions,
              scene.model.num_dofs() <= check_options.all_directions_up_to
                  ? " and every unit direction"
                  : "");
  std::printf("%-32s %-9s %12s %12s  %s\n", "force", "quantity", "rel. error", "abs. error",
              "verdict");
  bool all_passed = true;
  for (const DerivativeCheck& check : checks) {
    std::printf("%-32s %-9s %12.3e %12.3e  %s\n", check.force.c_str(),
                derivative_name(check.which), check.relative_error(), check.absolute_error,
                check.passed() ? "ok" : "FAILED");
    all_passed = all_passed && check.passed();
  }
  std::printf("\n%zu checks, %s\n", checks.size(), all_passed ? "all passed" : "some FAILED");
  return all_passed ? kExitOk : kExitGradingFailed;
}

}  // namespace fosssim
