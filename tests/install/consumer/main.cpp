// Loads a scene with an installed FOSSSim, runs it to its end and prints where it ended and its
// energy, and draws the last state into a PNG file (Cairo, through FOSSSim::pictures); a
// located error for a bad scene.
#include <iostream>

#include "core/error.h"
#include "core/force_evaluation.h"
#include "core/force_set.h"
#include "core/step/simulation.h"
#include "io/scene_loader.h"
#include "pictures/cairo_painter.h"
#include "render/scene_view.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: consumer SCENE PICTURE.png\n";
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
    const fosssim::SceneView view(scene, state, 64, 64);
    fosssim::write_png(view.compose(state), argv[2]);
    return 0;
  } catch (const fosssim::Error& error) {
    std::cerr << error.what() << "\n";
    return 1;
  }
}
