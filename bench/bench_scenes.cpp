#include "bench_scenes.h"

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

Scene tet_ball(int cells, std::string_view integrator) {
  Scene scene = start_scene(3, integrator, 0.005);
  const GeneratedMesh ball = generate_tet_ball(cells, 1.0);
  MeshMaterial material;
  material.k = 1e5;
  material.mass = {MassRule::kUniform, 1.0};
  add_mesh(scene, ball.mesh, material, select_extreme_vertices(ball.mesh, 1, false, 1e-3));
  scene.model.forces.push_back(std::make_unique<SimpleGravityForce<3>>(Vec<3>(0.0, -9.8, 0.0)));
  return scene;
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
