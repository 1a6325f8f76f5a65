// Test tool: changes one double of a trajectory file in place, the way a subtly wrong simulator
// would. Used by tests/oracle/candidates/perturbing_candidate.sh.
//
//   perturb_trajectory SCENE FILE FRAME PARTICLE COMPONENT DELTA
//     adds DELTA to the double of frame FRAME, particle PARTICLE, component COMPONENT
//     (0..dim-1: position x, y[, z]; dim..2dim-1: velocity; for a Theme 3 scene, body PARTICLE's
//     state X_x X_y θ V_x V_y ω, components 0..5, in the course's Theme 3 layout)
//   perturb_trajectory SCENE FILE FRAME PARTICLE COMPONENT flip-bit
//     flips the least significant bit of that double instead

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "io/scene_loader.h"
#include "io/trajectory_file.h"

int main(int argc, char** argv) {
  if (argc != 7) {
    std::cerr << "usage: perturb_trajectory SCENE FILE FRAME PARTICLE COMPONENT DELTA|flip-bit\n";
    return 2;
  }
  std::optional<fosssim::Scene> scene;
  try {
    scene.emplace(fosssim::load_scene_file(argv[1]));
  } catch (const fosssim::Error& error) {
    std::cerr << error.what() << "\n";
    return 2;
  }
  const int dim = scene->model.dim;
  const int dofs = scene->model.num_dofs();
  const long frame = std::atol(argv[3]);
  const int particle = std::atoi(argv[4]);
  const int component = std::atoi(argv[5]);
  if (particle < 0 || particle >= scene->model.num_particles() || component < 0 ||
      component >= 2 * dim) {
    std::cerr << "perturb_trajectory: particle or component out of range\n";
    return 2;
  }
  // Frame layout: dofs positions, then dofs velocities.
  const int index =
      component < dim ? dim * particle + component : dofs + dim * particle + component - dim;
  std::int64_t offset = frame * fosssim::trajectory_frame_bytes(dofs) + 8 * std::int64_t(index);
  if (scene->model.rigid_bodies) {  // io/rigid_trajectory.h: frame 0 holds 16B + 1 doubles,
    const std::int64_t bodies = scene->model.num_particles();  // later frames 12B + 1
    const std::int64_t before = frame == 0 ? 0 : 16 * bodies + 1 + (12 * bodies + 1) * (frame - 1);
    offset = 8 * (before + 6 * particle + component);
  }
  std::fstream file(argv[2], std::ios::in | std::ios::out | std::ios::binary);
  double value = 0.0;
  if (!file.seekg(offset) || !file.read(reinterpret_cast<char*>(&value), sizeof(value))) {
    std::cerr << "perturb_trajectory: cannot read frame " << frame << " of " << argv[2] << "\n";
    return 2;
  }
  if (std::strcmp(argv[6], "flip-bit") == 0) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof(bits));
    bits ^= 1u;
    std::memcpy(&value, &bits, sizeof(bits));
  } else {
    value += std::strtod(argv[6], nullptr);
  }
  if (!file.seekp(offset) || !file.write(reinterpret_cast<const char*>(&value), sizeof(value))) {
    std::cerr << "perturb_trajectory: cannot write " << argv[2] << "\n";
    return 2;
  }
  return 0;
}
