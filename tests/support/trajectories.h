#pragma once
// Writing a scene's trajectory as FOSSSim's headless run does, for tests that read or grade it.

#include <string>

#include "core/scene.h"
#include "core/step/simulation.h"
#include "io/trajectory_file.h"

namespace fosssim::testing {

/// Simulates `scene` from its initial state to its end and writes every frame, the initial one
/// first, to the trajectory file `path`.
inline void write_simulated_trajectory(const Scene& scene, const std::string& path) {
  TrajectoryWriter writer = TrajectoryWriter::open(path);
  Simulation simulation(scene.model, scene.initial);
  writer.write_frame(simulation.state());
  while (!simulation.finished()) {
    simulation.step();
    writer.write_frame(simulation.state());
  }
  writer.commit();
}

}  // namespace fosssim::testing
