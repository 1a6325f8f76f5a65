// Loads a scene with an installed FOSSSim, runs it to its end and prints where it ended and its
// energy; a located error for a bad scene.
#include <iostream>

#include "core/error.h"
#include "core/force_evaluation.h"
#include "core/force_set.h"
#include "core/step/simulation.h"
#include "io/scene_loader.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: consumer SCENE\n";
    return 2;
  }
  try {
    const fosssim::Scene scene = fosssim::load_scene_file(argv[1]);
    fosssim::Simulation simulation(scene.model, scene.initial);
    while (!simulation.finished()) simulation.step();
    const fosssim::State& state = simulation.state();
    const fosssim::ForceSet forces(scene.model);
    std::cout << "steps " << state.step << " time " << state.time << " energy "
              << fosssim::compute_kinetic_energy(scene.model, state.v) +
                     fosssim::compute_potential_energy(forces, state.q, state.v)
              << "\n";
    return 0;
  } catch (const fosssim::Error& error) {
    std::cerr << error.what() << "\n";
    return 1;
  }
}
