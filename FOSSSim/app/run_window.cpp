// The window mode of the command line: a run with its outputs, or a grading replay.

#include <filesystem>
#include <iostream>

#include "app/commands.h"
#include "app/interrupt.h"
#include "app/progress_bar.h"
#include "cli/exit_codes.h"
#include "io/trajectory_file.h"
#include "outputs/frame_outputs.h"
#include "viewer/stepper.h"
#include "viewer/window.h"

namespace fosssim {

namespace {

WindowSettings window_settings(const Scene& scene, const Options& options) {
  WindowSettings settings;
  settings.title = "FOSSSim: " + std::filesystem::path(scene.source).filename().string();
  settings.start_paused = options.paused == 1;
  settings.max_steps_per_second = scene.max_sim_frequency;
  settings.screenshot_path = options.window_screenshot;
  settings.screenshot_step = options.window_screenshot_step;
  settings.stop_requested = [] { return interrupt_requested(); };
  return settings;
}

/// Runs the scene in the window, feeding the outputs of -o, -g, -m and --energy-*; the mouse
/// can pull particles with the drag spring of ParticleGrab, an interaction force of the run.
int run_simulation_window(const Scene& scene, const Options& options) {
  FrameOutputs outputs =
      FrameOutputs::open(scene, output_requests(options), output_settings(options));
  ParticleGrab grab(scene);
  SimulationStepper stepper(scene, {&grab.interaction_force()},
                            Cancellation(&interrupt_requested));
  SceneView view(scene, stepper.state(), options.width, options.height);
  view.set_element_colors(element_colors(options));
  int status = kExitOk;
  bool outputs_open = true;
  auto close_outputs = [&](const std::string& why) {
    const std::string notes = outputs.abandon();
    outputs_open = false;
    if (!notes.empty()) std::cerr << "FOSSSim: " << why << "; " << notes << "\n";
  };
  auto guarded = [&](auto&& action) {
    if (!outputs_open) return;
    try {
      action();
    } catch (const Error& error) {
      std::cerr << "FOSSSim: error: " << error.what() << "\n";
      close_outputs("the outputs were stopped");
      status = exit_status(error.kind());
    }
  };
  guarded([&] { outputs.write(stepper.state(), view, nullptr, &stepper.simulation().integrator()); });

  WindowEvents events;
  events.stepped = [&](const State& state, const SceneView& v) {
    guarded([&] {
      outputs.write(state, v, &stepper.simulation().last_record(),
                    &stepper.simulation().integrator());
    });
  };
  events.finished = [&] {
    guarded([&] {
      outputs.commit();
      outputs_open = false;
      if (!outputs.empty() && !options.quiet && stderr_is_terminal()) {
        std::cerr << "FOSSSim: wrote " << outputs.describe() << "\n";
      }
    });
    for (const std::string& note : stepper.simulation().integrator().notes()) {
      std::cerr << "FOSSSim: note: " << note << "\n";
    }
    std::cout << "Simulation complete at time " << stepper.state().time << "." << std::endl;
  };
  events.failed = [&](const StepError& error) {
    std::cerr << "FOSSSim: error: " << scene.source << ": " << error.what() << "\n";
    if (outputs_open) close_outputs("the run failed");
    status = kExitSimulationFailed;
  };
  WindowSettings settings = window_settings(scene, options);
  settings.grab = &grab;
  run_window(stepper, view, settings, events);
  const std::string when = " at step " + std::to_string(stepper.state().step);
  if (interrupt_requested()) {  // the headless run's line, whether outputs were open or not
    const std::string notes = outputs_open ? outputs.abandon() : "";
    outputs_open = false;
    std::cerr << "FOSSSim: " << interrupted_at(stepper.state().step)
              << (notes.empty() ? "" : "; " + notes) << "\n";
    return kExitInterrupted;
  }
  if (outputs_open) close_outputs("the window was closed" + when);
  return status;
}

/// Replays the -i trajectory in the window, ringing the particles where it disagrees with the
/// reference; prints the course's report when the last step has been graded.
int run_grading_window(const Scene& scene, const Options& options) {
  TrajectoryReader file = open_trajectory(options.input, scene.model);
  GradingStepper stepper = [&] {
    try {
      return GradingStepper(
          StepGrader::open(scene, file, std::nullopt, Cancellation(&interrupt_requested)));
    } catch (const Error& error) {
      throw Error(error.kind(), options.input + ": " + error.what());
    }
  }();
  SceneView view(scene, stepper.state(), options.width, options.height);
  view.set_element_colors(element_colors(options));
  std::optional<int> status;
  WindowEvents events;
  events.finished = [&] { status = report_grade(scene, options, stepper.grader().report()); };
  events.failed = [&](const StepError&) {
    status = report_grade(scene, options, stepper.grader().report());
  };
  run_window(stepper, view, window_settings(scene, options), events);
  if (!status) {
    std::cerr << "FOSSSim: the window was closed at step " << stepper.state().step << " of "
              << stepper.grader().report().steps << ", before grading finished; no grade\n";
    return kExitInterrupted;
  }
  return *status;
}

}  // namespace

int run_window(const Scene& scene, const Options& options) {
  check_display();
  if (!options.input.empty()) return run_grading_window(scene, options);
  return run_simulation_window(scene, options);
}

}  // namespace fosssim
