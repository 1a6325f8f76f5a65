#include <cstring>
#include <iostream>

#include "app/commands.h"
#include "app/frame_outputs.h"
#include "app/interrupt.h"
#include "app/progress_bar.h"
#include "cli/exit_codes.h"
#include "core/step/simulation.h"
#include "core/step_error.h"
#include "render/scene_view.h"
#include "scripting/step_hooks.h"

namespace fosssim {

namespace {
/// "; <what the outputs kept>", or nothing.
std::string kept_note(FrameOutputs& outputs) {
  const std::string notes = outputs.abandon();
  return notes.empty() ? "" : "; " + notes;
}
}  // namespace

int run_headless(const Scene& scene, const Options& options) {
  FrameOutputs outputs = FrameOutputs::open(scene, options);
  try {
    Simulation simulation(scene.model, scene.initial, scripted_additions(scene));
    SceneView view(scene, simulation.state(), options.width, options.height);
    ProgressBar progress("simulating", scene.model.num_steps(),
                         !options.quiet && stderr_is_terminal());
    try {
      outputs.write(simulation.state(), view);
      while (!simulation.finished()) {
        if (interrupt_requested()) {
          progress.finish();
          std::cerr << "FOSSSim: interrupted by signal " << interrupt_signal() << " ("
                    << strsignal(interrupt_signal()) << ") at step " << simulation.state().step
                    << kept_note(outputs) << "\n";
          return kExitInterrupted;
        }
        simulation.step();
        view.record(simulation.state());
        outputs.write(simulation.state(), view, &simulation.last_record());
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
