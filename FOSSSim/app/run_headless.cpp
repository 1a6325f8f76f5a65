#include <iostream>
#include <optional>

#include "app/commands.h"
#include "app/exit_codes.h"
#include "app/interrupt.h"
#include "app/progress_bar.h"
#include "core/simulation.h"
#include "core/step_error.h"
#include "io/trajectory_file.h"

namespace fosssim {

namespace {
/// "; the 12 frames computed so far are in out.bin.incomplete", or nothing without -o.
std::string kept_frames_note(std::optional<TrajectoryWriter>& writer, std::int64_t frames) {
  if (!writer) return "";
  return "; the " + std::to_string(frames) + " frames computed so far are in " +
         writer->abandon() + " (" + writer->path() + " was not written)";
}
}  // namespace

int run_headless(const Scene& scene, const Options& options) {
  std::optional<TrajectoryWriter> writer;
  if (!options.output.empty()) {
    auto opened = TrajectoryWriter::open(options.output);
    if (!opened) {
      std::cerr << "FOSSSim: error: " << opened.error() << "\n";
      return kExitIoError;
    }
    writer.emplace(std::move(opened).value());
  }
  Simulation simulation(scene.model, scene.initial);
  ProgressBar progress("simulating", scene.model.num_steps(),
                       !options.quiet && stderr_is_terminal());
  try {
    if (writer) writer->write_frame(simulation.state());
    while (!simulation.finished()) {
      if (interrupt_requested()) {
        progress.finish();
        std::cerr << "FOSSSim: interrupted at step " << simulation.state().step
                  << kept_frames_note(writer, simulation.state().step + 1) << "\n";
        return kExitInterrupted;
      }
      simulation.step();
      if (writer) writer->write_frame(simulation.state());
      progress.update(simulation.state().step);
    }
    progress.finish();
    if (writer) writer->commit();
  } catch (const StepError& error) {
    progress.finish();
    std::cerr << "FOSSSim: error: " << scene.source << ": " << error.what()
              << kept_frames_note(writer, error.step()) << "\n";
    return kExitSimulationFailed;
  } catch (const std::runtime_error& error) {
    progress.finish();
    std::cerr << "FOSSSim: error: " << error.what() << "\n";
    return kExitIoError;
  }
  for (const std::string& note : simulation.integrator().notes()) {
    std::cerr << "FOSSSim: note: " << note << "\n";
  }
  std::cout << "Simulation complete at time " << simulation.state().time << ". Exiting."
            << std::endl;
  return kExitOk;
}

}  // namespace fosssim
