#include "scene_trajectory.h"

#include "core/step/simulation.h"
#include "io/rigid_trajectory.h"
#include "io/trajectory_file.h"
#include "io/trajectory_steps.h"
#include "scripting/step_hooks.h"

namespace fosssim {

double write_scene_trajectory(const Scene& scene, const std::string& path) {
  Simulation simulation(scene.model, scene.initial, scripted_additions(scene));
  TrajectoryWriter writer = TrajectoryWriter::open(path);
  if (scene.model.rigid_bodies) {
    RigidTrajectoryWriter rigid(std::move(writer), scene.model);
    rigid.write(simulation.state());
    while (!simulation.finished()) {
      simulation.step();
      rigid.write(simulation.state());
    }
    rigid.commit();
  } else {
    const TrajectoryLayout layout = trajectory_layout(scene.model);
    write_trajectory_state(writer, layout, simulation.state(), nullptr);
    while (!simulation.finished()) {
      simulation.step();
      write_trajectory_state(writer, layout, simulation.state(), &simulation.last_record());
    }
    writer.commit();
  }
  return simulation.state().time;
}

}  // namespace fosssim
