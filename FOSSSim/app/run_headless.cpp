#include <cstring>
#include <iostream>
#include <optional>

#include "app/commands.h"
#include "app/interrupt.h"
#include "app/progress_bar.h"
#include "cli/exit_codes.h"
#include "core/step/cancellation.h"
#include "core/step/simulation.h"
#include "core/step_error.h"
#include "outputs/frame_outputs.h"
#include "render/camera.h"
#include "render/scene_view.h"
#include "scripting/step_hooks.h"

namespace fosssim {

namespace {
/// The scene's additions, with steps that end early once a signal arrives (app/interrupt.h):
/// long iterations inside a step ask it, so a step that would take minutes stops at once.
StepAdditions interruptible_additions(const Scene& scene) {
  StepAdditions additions = scripted_additions(scene);
  additions.cancellation = Cancellation(&interrupt_requested);
  return additions;
}

/// "; <what the outputs kept>", or nothing.
std::string kept_note(FrameOutputs& outputs) {
  const std::string notes = outputs.abandon();
  return notes.empty() ? "" : "; " + notes;
}

/// True when the run writes pictures or a movie and the scene leaves their camera to the
/// particles' positions (no 2D <viewport>; no <camera3d> or --view fixing target and distance).
bool pictures_frame_positions(const Scene& scene, const Options& options) {
  if (!asks_for_pictures(options) || options.frame != "run") return false;
  const Appearance& look = scene.appearance;
  if (scene.model.dim == 3 && look.camera3d) {
    return !(look.camera3d->target && look.camera3d->distance);
  }
  return !look.viewport;
}

/// The corners (low, high) of the box the particle centres cover over the whole run, as the
/// positions of two particles: the scene is run once without outputs, so that the pictures'
/// camera frames all of the run and not only its first state. A failed step or an interrupt
/// ends this pass with what it covered; the run proper then reports them.
Vector whole_run_corners(const Scene& scene, const Options& options) {
  const int dim = scene.model.dim;
  auto [low, high] = compute_bounding_box(scene.initial.q, dim);
  ProgressBar progress("framing the pictures", scene.model.num_steps(),
                       choose_progress_style(options.progress, options.quiet),
                       options.progress_every);
  try {
    Simulation simulation(scene.model, scene.initial, interruptible_additions(scene));
    while (!simulation.finished() && !interrupt_requested()) {
      simulation.step();
      const auto [step_low, step_high] = compute_bounding_box(simulation.state().q, dim);
      low = low.cwiseMin(step_low);
      high = high.cwiseMax(step_high);
      progress.update(simulation.state().step);
    }
  } catch (const StepError&) {
  } catch (const StepCancelled&) {
  }
  progress.finish();
  Vector corners(2 * dim);
  corners << low.head(dim), high.head(dim);
  return corners;
}
}  // namespace

int run_headless(const Scene& scene, const Options& options) {
  FrameOutputs outputs =
      FrameOutputs::open(scene, output_requests(options), output_settings(options));
  try {
    std::optional<Vector> frame;
    if (pictures_frame_positions(scene, options)) frame = whole_run_corners(scene, options);
    Simulation simulation(scene.model, scene.initial, interruptible_additions(scene));
    SceneView view(scene, simulation.state(), options.width, options.height,
                   frame ? &*frame : nullptr);
    view.set_element_colors(element_colors(options));
    ProgressBar progress("simulating", scene.model.num_steps(),
                         choose_progress_style(options.progress, options.quiet),
                         options.progress_every);
    try {
      outputs.write(simulation.state(), view, nullptr, &simulation.integrator());
      const auto interrupted = [&] {
        progress.finish();
        std::cerr << "FOSSSim: " << interrupted_at(simulation.state().step)
                  << kept_note(outputs) << "\n";
        return kExitInterrupted;
      };
      while (!simulation.finished()) {
        if (interrupt_requested()) return interrupted();
        try {
          simulation.step();
        } catch (const StepCancelled&) {
          return interrupted();  // within the step: the frames so far are kept
        }
        view.record(simulation.state());
        outputs.write(simulation.state(), view, &simulation.last_record(),
                      &simulation.integrator());
        progress.update(simulation.state().step);
      }
      progress.finish();
      outputs.commit();
    } catch (const std::exception&) {
      progress.finish();
      throw;
    }
    for (const std::string& note : simulation.integrator().notes()) {
      std::cerr << "FOSSSim: note: " << note << "\n";
    }
    if (!outputs.empty() && !options.quiet && stderr_is_terminal()) {
      std::cerr << "FOSSSim: wrote " << outputs.describe() << "\n";
    }
    std::cout << "Simulation complete at time " << simulation.state().time << ". Exiting."
              << std::endl;
    return kExitOk;
  } catch (const StepError& error) {
    std::cerr << "FOSSSim: error: " << scene.source << ": " << error.what() << kept_note(outputs)
              << "\n";
    return kExitSimulationFailed;
  } catch (const std::exception& failure) {
    return report_failure(std::cerr, failure, outputs.abandon());
  }
}

}  // namespace fosssim
