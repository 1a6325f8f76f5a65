#include "bench_scenes.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "core/forces/constant_force.h"
#include "core/forces/simple_gravity_force.h"
#include "mesh/generators.h"
#include "mesh/mesh_scene.h"

namespace fosssim::bench {

namespace {

Scene start_scene(int dim, std::string_view integrator, double dt) {
  Scene scene;
  scene.model.dim = dim;
  scene.model.integrator.use(integrator_method(integrator));
  scene.model.integrator.dt = dt;
  return scene;
}

void add_mesh(Scene& scene, const Mesh& mesh, const MeshMaterial& material,
              const std::vector<int>& pins) {
  scene.model.forces.push_back(append_mesh(scene, mesh, material, pins, "mesh"));
}

}  // namespace

void set_option(Scene& scene, std::string_view name, double value) {
  if (scene.model.integrator.options.has(name)) scene.model.integrator.options.set(name, value);
}

void set_option(Scene& scene, std::string_view name, std::string_view choice) {
  if (scene.model.integrator.options.has(name)) scene.model.integrator.options.set(name, choice);
}

Scene cloth_3d(int nx, std::string_view integrator, double k) {
  Scene scene = start_scene(3, integrator, 1.0 / 30.0);
  set_option(scene, "iterations", 10);
  const GeneratedMesh cloth = generate_cloth(nx, nx, 1.0, 1.0, true, true);
  MeshMaterial material;
  material.k = k;
  material.mass = {MassRule::kTotal, 1.0};
  add_mesh(scene, cloth.mesh, material, *cloth.find_pins("corners"));
  scene.model.forces.push_back(std::make_unique<SimpleGravityForce<3>>(Vec<3>(0.0, -9.8, 0.0)));
  return scene;
}

Scene damped_cloth_2d(int nx, std::string_view integrator) {
  Scene scene = start_scene(2, integrator, 0.01);
  const GeneratedMesh cloth = generate_cloth(nx, nx, 1.0, 1.0, false, false);
  MeshMaterial material;
  material.k = 1000.0;
  material.b = 0.5;
  material.mass = {MassRule::kTotal, 1.0};
  add_mesh(scene, cloth.mesh, material, *cloth.find_pins("corners"));
  scene.model.forces.push_back(std::make_unique<SimpleGravityForce<2>>(Vec<2>(0.0, -9.8)));
  return scene;
}

Scene assignment_tet_scene(const Mesh& mesh, double pin_within, std::string_view integrator) {
  Scene scene = start_scene(3, integrator, 0.005);
  MeshMaterial material;
  material.k = 1e5;
  material.mass = {MassRule::kUniform, 1.0};
  add_mesh(scene, mesh, material, select_extreme_vertices(mesh, 1, false, pin_within));
  scene.model.forces.push_back(std::make_unique<SimpleGravityForce<3>>(Vec<3>(0.0, -9.8, 0.0)));
  return scene;
}

Scene bunny_stand_in(std::string_view integrator) {
  constexpr int nx = 5, ny = 13, nz = 7;  // cubes
  constexpr double cell = 12.0;           // units of the bunny's file, about 160 tall
  Mesh mesh;
  const auto index = [](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) mesh.vertices.emplace_back(i * cell, j * cell, k * cell);
    }
  }
  // Five tets per cube: four corner tets and the central one, the corners chosen by the
  // cube's parity so that neighbouring cubes split their shared face along the same diagonal.
  using Corner = std::array<int, 3>;
  const std::array<std::array<Corner, 4>, 5> even = {{
      {{{0, 0, 0}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}}},
      {{{1, 0, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 1}}},
      {{{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 1}}},
      {{{0, 0, 1}, {0, 0, 0}, {1, 0, 1}, {0, 1, 1}}},
      {{{1, 1, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}}},
  }};
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const bool odd = (i + j + k) % 2 == 1;  // odd cubes: the even pattern mirrored in x
        for (const auto& tet : even) {
          std::array<int, 4> t{};
          for (int c = 0; c < 4; ++c) {
            const int x = odd ? 1 - tet[c][0] : tet[c][0];
            t[c] = index(i + x, j + tet[c][1], k + tet[c][2]);
          }
          if (compute_tet_volume(mesh, t) < 0.0) std::swap(t[2], t[3]);
          mesh.tets.push_back(t);
        }
      }
    }
  }
  std::vector<int> pins;  // 16 bottom vertices at one corner (the bunny: 17 feet vertices)
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i < 4; ++i) pins.push_back(index(i, 0, k));
  }
  std::sort(pins.begin(), pins.end());
  Scene scene = start_scene(3, integrator, 0.005);
  MeshMaterial material;
  material.k = 1e5;
  material.mass = {MassRule::kUniform, 1.0};
  add_mesh(scene, mesh, material, pins);
  scene.model.forces.push_back(std::make_unique<SimpleGravityForce<3>>(Vec<3>(0.0, -9.8, 0.0)));
  return scene;
}

Scene tet_ball(int cells, std::string_view integrator) {
  return assignment_tet_scene(generate_tet_ball(cells, 1.0).mesh, 1e-3, integrator);
}

Scene flag(int nx, int ny, std::string_view integrator) {
  Scene scene = start_scene(3, integrator, 1.0 / 30.0);
  set_option(scene, "iterations", 50);
  set_option(scene, "pins", "penalty");
  set_option(scene, "penalty", 1e10);
  const GeneratedMesh cloth = generate_cloth(nx, ny, 2.0, 1.0, false, false);
  std::vector<int> pole;
  for (int r = 0; r < ny; ++r) pole.push_back(r * nx);
  MeshMaterial material;
  material.k = 20000.0;
  material.mass = {MassRule::kUniform, 1.0};
  add_mesh(scene, cloth.mesh, material, pole);
  scene.model.forces.push_back(std::make_unique<ConstantForce<3>>(Vec<3>(0.0, -9.8, 0.0)));
  return scene;
}

}  // namespace fosssim::bench
