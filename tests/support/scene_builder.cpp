#include "support/scene_builder.h"

#include "core/forces/drag_damping_force.h"
#include "core/forces/gravitational_force.h"
#include "core/forces/make_for_dim.h"
#include "core/forces/simple_gravity_force.h"
#include "core/forces/spring_force.h"
#include "core/integrators/integrator_registry.h"
#include "core/step/simulation.h"
#include "mesh/generators.h"
#include "mesh/mesh_scene.h"

namespace fosssim::testing {

TestScene::TestScene(int dim, std::string_view integrator, double dt) {
  model.dim = dim;
  model.integrator.use(integrator_method(integrator));
  model.integrator.dt = dt;
  initial.q.resize(0);
  initial.v.resize(0);
}

int TestScene::add_particle(double m, const Vector& x, const Vector& v, bool fixed,
                            double radius) {
  const int dim = model.dim;
  const Eigen::Index n = initial.q.size();
  initial.q.conservativeResize(n + dim);
  initial.v.conservativeResize(n + dim);
  model.mass.conservativeResize(n + dim);
  initial.q.tail(dim) = x;
  initial.v.tail(dim) = v;
  model.mass.tail(dim).setConstant(m);
  model.fixed.push_back(fixed);
  model.particle_radius.push_back(radius);
  appearance.particle_color.push_back(Appearance::kDefaultParticleColor);
  return model.num_particles() - 1;
}

int TestScene::add_edge(int i, int j, double radius) {
  model.edges.push_back({i, j});
  model.edge_radius.push_back(radius);
  appearance.edge_color.push_back(Appearance::kDefaultEdgeColor);
  return static_cast<int>(model.edges.size()) - 1;
}

void TestScene::add_half_plane(const Vector& point, const Vector& normal) {
  model.half_planes.push_back({point, normal});
  appearance.half_plane_color.push_back(Appearance::kDefaultHalfPlaneColor);
}

void TestScene::add_spring(int i, int j, double k, double l0, double b) {
  add_edge(i, j);
  add_force(make_for_dim<SpringForce>(model.dim, i, j, k, l0, b));
}

void TestScene::add_gravitation(int i, int j, double G) {
  add_force(make_for_dim<GravitationalForce>(model.dim, i, j, G));
}

void TestScene::add_drag(double b) { add_force(make_for_dim<DragDampingForce>(model.dim, b)); }

void TestScene::add_simple_gravity(const Vector& g) {
  if (model.dim == 3) {
    add_force(std::make_unique<SimpleGravityForce<3>>(Vec<3>(g)));
  } else {
    add_force(std::make_unique<SimpleGravityForce<2>>(Vec<2>(g)));
  }
}

TestScene particles(int dim, const std::vector<double>& positions, double m,
                    const std::vector<bool>& fixed) {
  TestScene scene(dim);
  const int n = static_cast<int>(positions.size()) / dim;
  for (int p = 0; p < n; ++p) {
    scene.add_particle(m, Eigen::Map<const Vector>(positions.data() + dim * p, dim),
                       Vector::Zero(dim), fixed.at(p));
  }
  return scene;
}

TestScene particles_at(const std::vector<Eigen::Vector3d>& points) {
  TestScene scene(3);
  for (const Eigen::Vector3d& point : points) scene.add_particle(1.0, point, Vector::Zero(3));
  scene.model.particle_radius.assign(points.size(), 0.05);
  return scene;
}

TestScene cloth(int nx, double k, std::string_view integrator, double dt, bool horizontal,
                const std::string& pins, double b) {
  TestScene scene(3, integrator, dt);
  GeneratedMesh generated = generate_cloth(nx, nx, 1.0, 1.0, horizontal, true);
  MeshMaterial material;
  material.k = k;
  material.b = b;
  material.mass = {MassRule::kTotal, 0.1};
  auto springs = append_mesh(scene, generated.mesh, material, *generated.find_pins(pins), "cloth");
  scene.model.forces.push_back(std::move(springs));
  scene.add_simple_gravity(vec({0.0, -9.8, 0.0}));
  return scene;
}

State run_steps(const SceneModel& model, State state, std::int64_t steps) {
  const auto integrator = make_integrator(model);
  for (std::int64_t s = 0; s < steps; ++s) integrator->step(state);
  return state;
}

State moving_cloth_state() {
  const TestScene newton = cloth(7, 20.0, "implicit-euler", 1.0 / 30.0);
  Simulation simulation(newton.model, newton.initial);
  for (int step = 0; step < 12; ++step) simulation.step();
  return simulation.state();
}

}  // namespace fosssim::testing
