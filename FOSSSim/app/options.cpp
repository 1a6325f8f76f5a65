#include "app/options.h"

#include <cmath>

#include "core/text.h"

namespace fosssim {

void add_options(CLI::App& app, Options& options) {
  app.description(
      "FOSSSim: a physically based particle and mass-spring simulator.\n"
      "Runs a scene in the course's XML format, writes its trajectory (-o), or grades a\n"
      "trajectory against the scene's integrator with the course's criteria (-i).");
  app.add_option("-s,--scene", options.scene, "Scene file (XML) to load")->required();
  app.add_option("-d,--display", options.display,
                 "1: open the interactive window; 0: run headless to the scene's end")
      ->check(CLI::IsMember({0, 1}))
      ->capture_default_str();
  app.add_option("-p,--paused", options.paused, "1: start the window paused; 0: start running")
      ->check(CLI::IsMember({0, 1}))
      ->capture_default_str();
  auto* output = app.add_option(
      "-o,--output", options.output,
      "Write the trajectory here (frames of positions then velocities, little-endian doubles).\n"
      "It appears only when the run completes; a failed run leaves FILE.incomplete");
  auto* input = app.add_option(
      "-i,--input", options.input,
      "Grading mode: replay this trajectory step by step against the scene's integrator,\n"
      "print the course's report, write the residual file; exit 0 if it passes, 1 if not");
  output->excludes(input);
  input->excludes(output);
  app.add_option("--duration", options.duration, "Override the scene's duration (seconds, >= 0)");
  app.add_option("--dt", options.dt, "Override the scene's time step (seconds, > 0)");
  app.add_option("--newton-max-iterations", options.newton_max_iterations,
                 "Implicit Euler: give up on a step after this many Newton iterations (default 200)");
  app.add_option("--newton-tolerance", options.newton_tolerance,
                 "Implicit Euler: stop when the Newton correction's L2 norm is below this "
                 "(default 1e-9, the course's value)");
  app.add_option("--residual-file", options.residual_file,
                 "Grading mode: where to write the per-criterion residuals")
      ->capture_default_str();
  app.add_flag("--check-derivatives", options.check_derivatives,
               "Check every force's gradient and Hessians against finite differences at the\n"
               "scene's initial state, print a table and exit (1 if any check fails)");
  app.add_flag("-q,--quiet", options.quiet, "No progress bar and no description");
  app.set_version_flag("--version", "FOSSSim 0.1.0");
  app.footer(
      "Exit status: 0 success or passed; 1 grading failed; 2 bad command line, scene or\n"
      "trajectory file; 3 a step failed (non-finite state, Newton did not converge);\n"
      "4 an output file could not be written; 130 interrupted.\n\n"
      "Examples:\n"
      "  FOSSSim -s assets/t1m1/springs_single.xml -d 0 -o out.bin\n"
      "  FOSSSim -s assets/t1m1/springs_single.xml -d 0 -i out.bin\n"
      "  FOSSSim -s scene.xml -d 0 --dt 0.001 --duration 2 -o fine.bin\n"
      "  FOSSSim -s scene.xml --check-derivatives");
}

std::optional<std::string> apply_overrides(const Options& options, Scene& scene) {
  SceneModel& model = scene.model;
  if (options.duration) {
    if (!std::isfinite(*options.duration) || *options.duration < 0.0)
      return "--duration must be a finite number >= 0, found " + to_text(*options.duration);
    model.duration = *options.duration;
  }
  if (options.dt) {
    if (!std::isfinite(*options.dt) || *options.dt <= 0.0)
      return "--dt must be a finite number > 0, found " + to_text(*options.dt);
    model.integrator.dt = *options.dt;
  }
  if (options.newton_max_iterations) {
    if (*options.newton_max_iterations < 1)
      return "--newton-max-iterations must be at least 1, found " +
             std::to_string(*options.newton_max_iterations);
    model.integrator.newton.max_iterations = *options.newton_max_iterations;
  }
  if (options.newton_tolerance) {
    if (!std::isfinite(*options.newton_tolerance) || *options.newton_tolerance <= 0.0)
      return "--newton-tolerance must be a finite number > 0, found " +
             to_text(*options.newton_tolerance);
    model.integrator.newton.tolerance = *options.newton_tolerance;
  }
  return std::nullopt;
}

}  // namespace fosssim
