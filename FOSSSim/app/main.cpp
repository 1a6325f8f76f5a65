// FOSSSim command line: loads a scene, then runs it headless (writing trajectories, pictures,
// movies, energy plots), grades a trajectory against it, checks its derivatives, or opens the
// window. Only this file turns failures into exit statuses.

#include <algorithm>
#include <iostream>

#include "app/commands.h"
#include "app/interrupt.h"
#include "app/options.h"
#include "app/solver_threads.h"
#include "cli/exit_codes.h"
#include "cli/parse_command_line.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/solvers/memory_policy.h"
#include "io/input_files.h"
#include "io/scene_loader.h"
#include "scripting/step_hooks.h"

namespace fosssim {
namespace {

/// Loads the scene, applies the overrides and runs what the options ask for.
int run(Options& options) {
  try {
    check_picture_options(options);
  } catch (const Error& error) {
    std::cerr << "FOSSSim: error: " << error.what() << "\nRun FOSSSim --help for the options.\n";
    return exit_status(error.kind());
  }
  const Limits limits = limits_of(options);
  InputFiles files(limits);
  Scene scene = load_scene_file(options.scene, files);
  try {
    apply_overrides(options, scene);
    if (!options.check_derivatives) check_step_count(scene.model, limits);
    check_outputs_distinct(options);
    check_outputs_spare_inputs(options, scene);
  } catch (const Error&) {
    for (const std::string& warning : scene.warnings) std::cerr << warning << "\n";
    throw;
  }
  for (const std::string& warning : scene.warnings) std::cerr << warning << "\n";
  if (!set_solver_threads(options.threads)) {
    if (options.threads > 1) {
      std::cerr << "FOSSSim: note: --threads " << options.threads
                << " has no effect: this program's BLAS is not OpenBLAS\n";
    }
  } else if (options.threads > 1) {
    // Bits may depend on the count (docs/solvers.md): the run's output says which it used.
    std::cerr << "FOSSSim: note: the sparse solvers use " << options.threads
              << " BLAS threads (--threads); large implicit steps may differ in their last bits "
                 "from a run with another count\n";
  }
  if (!scene.description.empty() && !options.quiet) std::cout << scene.description << std::endl;

  if (options.check_derivatives) return run_derivative_check(scene, options);
  const std::vector<std::string> tags = known_scene_tags();
  if (!scene.tag.empty() && std::find(tags.begin(), tags.end(), scene.tag) == tags.end() &&
      !options.quiet) {
    std::cerr << "FOSSSim: note: scenetag '" << scene.tag
              << "' has no scripted behaviour in FOSSSim; the scene runs without it\n";
  }
  install_interrupt_handler();
  if (options.display == 1) return run_window(scene, options);
  if (!options.input.empty()) return run_grading(scene, options);
  return run_headless(scene, options);
}

}  // namespace
}  // namespace fosssim

int main(int argc, char** argv) {
  using namespace fosssim;
  return_large_blocks_to_system();
  Options options;
  CLI::App app{"FOSSSim", "FOSSSim"};
  add_options(app, options);
  if (auto status = parse_command_line(app, argc, argv)) return *status;
  options.display_given = app.count("--display") > 0;
  try {
    return run(options);
  } catch (const std::exception& failure) {
    return report_failure(std::cerr, failure);
  }
}
