#pragma once
// Building scenes in C++ for tests, without scene files: particles, edges and forces one by one,
// rows of particles, generated cloth, and the integrator of a model as its own class.

#include <Eigen/Dense>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/integrators/integrator.h"
#include "core/scene.h"
#include "core/state.h"
#include "core/types.h"

namespace fosssim::testing {

/// A vector from a brace list: vec({1.0, 2.0}).
inline Vector vec(std::initializer_list<double> values) {
  Vector out(static_cast<Eigen::Index>(values.size()));
  Eigen::Index k = 0;
  for (double value : values) out[k++] = value;
  return out;
}

/// A scene built in code: a Scene (model, initial state, appearance) with the steps to build
/// it. Particles and edges get the default appearance, as in a scene file that gives none.
struct TestScene : Scene {
  /// An empty scene of dimension `dim` stepped by `integrator` (the canonical name of a method
  /// of core/integrators/integrator_registry.h) with time step dt.
  explicit TestScene(int dim, std::string_view integrator = "explicit-euler", double dt = 0.01);
  /// A scene loaded from a file, to add to it.
  explicit TestScene(Scene scene) : Scene(std::move(scene)) {}

  /// Appends a particle of mass m at x with velocity v (both of size dim) and this radius;
  /// returns its index.
  int add_particle(double m, const Vector& x, const Vector& v, bool fixed = false,
                   double radius = SceneModel::kDefaultParticleRadius);
  /// Appends the edge (i, j) of this radius; returns its index.
  int add_edge(int i, int j, double radius = SceneModel::kDefaultEdgeRadius);
  /// Appends the half-plane through `point` with outward `normal` (both of size dim).
  void add_half_plane(const Vector& point, const Vector& normal);

  /// Appends a force; forces are summed in the order they are added.
  template <typename ForceT>
  ForceT& add_force(std::unique_ptr<ForceT> force) {
    ForceT& out = *force;
    model.forces.push_back(std::move(force));
    return out;
  }

  /// Appends the edge (i, j) and an undamped or damped spring on it.
  void add_spring(int i, int j, double k, double l0, double b = 0.0);
  /// Appends Newtonian gravity between i and j.
  void add_gravitation(int i, int j, double G);
  /// Appends linear drag on every particle.
  void add_drag(double b);
  /// Appends a uniform gravitational acceleration g (size dim).
  void add_simple_gravity(const Vector& g);
};

/// Particles of mass m at `positions` (dim values each), at rest, fixed where `fixed` says;
/// explicit Euler with dt = 0.01 until the test chooses otherwise.
TestScene particles(int dim, const std::vector<double>& positions, double m,
                    const std::vector<bool>& fixed);

/// 3D particles of mass 1 at `points`, at rest, drawn with radius 0.05; dt = 0.01; nothing else.
TestScene particles_at(const std::vector<Eigen::Vector3d>& points);

/// A generated cloth (nx × nx vertices, a 1 m square, total mass 0.1 kg) with springs k and
/// damping b, pinned by the named set of mesh/generators.h, under gravity (0, -9.8, 0), stepped
/// by `integrator` with time step dt.
TestScene cloth(int nx, double k, std::string_view integrator, double dt, bool horizontal = true,
                const std::string& pins = "corners", double b = 0.0);

/// cloth(7, 20, "implicit-euler", 1/30) 12 steps after release, springs stretched and
/// compressed: a state in motion for tests that compare implicit solvers from one start.
State moving_cloth_state();

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

/// Runs `steps` steps of the model's integrator from `state` and returns the result.
State run_steps(const SceneModel& model, State state, std::int64_t steps);

}  // namespace fosssim::testing
