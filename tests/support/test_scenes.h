#pragma once
// Small models built in code for the core 3D tests.

#include <memory>
#include <stdexcept>
#include <vector>

#include "core/forces/simple_gravity_force.h"
#include "core/forces/spring_force.h"
#include "core/integrators/integrator.h"
#include "core/scene.h"
#include "mesh/generators.h"
#include "mesh/mesh_scene.h"

namespace fosssim::testing {

/// The model's integrator (make_integrator), bound to it and `interaction`, as the method's
/// class T (ImplicitEuler, LocalGlobal<3>, ...), for tests that ask it what it did.
template <typename T>
std::unique_ptr<T> bound_integrator(const SceneModel& model,
                                    std::vector<const Force*> interaction = {}) {
  std::unique_ptr<Integrator> integrator = make_integrator(model, std::move(interaction));
  T* typed = dynamic_cast<T*>(integrator.get());
  if (typed == nullptr) throw std::logic_error("the model's integrator is another method");
  integrator.release();
  return std::unique_ptr<T>(typed);
}

/// A scene of particles at `positions` (dim·n values) with masses m, at rest unless v given.
inline Scene particles(int dim, const std::vector<double>& positions, double m,
                       const std::vector<bool>& fixed) {
  Scene scene;
  const int n = static_cast<int>(positions.size()) / dim;
  scene.model.dim = dim;
  scene.model.mass = Vector::Constant(dim * n, m);
  scene.model.fixed = fixed;
  scene.initial.q = Eigen::Map<const Vector>(positions.data(), dim * n);
  scene.initial.v = Vector::Zero(dim * n);
  return scene;
}

/// Adds a SpringForce between particles i and j.
inline void add_spring(Scene& scene, int i, int j, double k, double l0, double b = 0.0) {
  if (scene.model.dim == 3) {
    scene.model.forces.push_back(std::make_unique<SpringForce<3>>(i, j, k, l0, b));
  } else {
    scene.model.forces.push_back(std::make_unique<SpringForce<2>>(i, j, k, l0, b));
  }
}

/// Adds gravity (0, -g, 0) as a mass-proportional acceleration.
inline void add_gravity(Scene& scene, double g) {
  if (scene.model.dim == 3) {
    scene.model.forces.push_back(std::make_unique<SimpleGravityForce<3>>(Vec<3>(0.0, -g, 0.0)));
  } else {
    scene.model.forces.push_back(std::make_unique<SimpleGravityForce<2>>(Vec<2>(0.0, -g)));
  }
}

/// A generated cloth (nx × nx vertices, 1 m square, total mass 0.1 kg by default) pinned by
/// the named set, with gravity 9.8 and the given integrator.
inline Scene cloth(int nx, double k, std::string_view kind, double dt, bool horizontal = true,
                   const std::string& pins = "corners", double b = 0.0) {
  Scene scene;
  scene.model.dim = 3;
  scene.model.integrator.use(integrator_method(kind));
  scene.model.integrator.dt = dt;
  GeneratedMesh generated = generate_cloth(nx, nx, 1.0, 1.0, horizontal, true);
  MeshMaterial material;
  material.k = k;
  material.b = b;
  material.mass = {MassRule::kTotal, 0.1};
  auto springs = append_mesh(scene, generated.mesh, material, *generated.find_pins(pins), "cloth");
  scene.model.forces.push_back(std::move(springs).value());
  add_gravity(scene, 9.8);
  return scene;
}

}  // namespace fosssim::testing
