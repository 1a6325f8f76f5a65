#pragma once
// What a scene *is*: everything that does not change while it runs.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/collisions/collision_settings.h"
#include "core/force.h"
#include "core/integrators/integrator_registry.h"
#include "core/types.h"

namespace fosssim {

struct RigidBodies;  // core/rigid/rigid_bodies.h

/// How a scene steps: the method (an entry of core/integrators/integrator_registry.h), the time
/// step, and the method's own settings.
struct IntegratorSettings {
  const IntegratorMethod* method = &default_integrator_method();
  double dt = 0.01;                       ///< time step h, seconds
  OptionValues options{method->options};  ///< values of method->options

  /// Switches to `m` with its default settings.
  void use(const IntegratorMethod& m) {
    method = &m;
    options = OptionValues(m.options);
  }
};

/// A line segment between two particles; springs live on edges.
struct Edge {
  int i = 0;
  int j = 0;
};

/// The fixed part of a scene: particles' masses, fixed flags and radii, topology, forces in the
/// course's summation order (docs/scene-format.md), contact, and how to step. Positions and
/// velocities live in State.
struct SceneModel {
  static constexpr double kDefaultParticleRadius = 0.1;
  static constexpr double kDefaultEdgeRadius = 0.015;

  /// Coordinates per particle: 2 or 3 for particles in 2D or 3D; 3 for planar rigid bodies,
  /// whose "particles" are bodies with coordinates (X_x, X_y, θ) (rigid_bodies is then set).
  int dim = 2;
  Vector mass;              ///< per degree of freedom: [m0, m0, m1, m1, ...], size dim*n
  std::vector<bool> fixed;  ///< per particle; fixed particles receive no force
  /// Set for a scene of planar rigid bodies (docs/rigid-bodies.md): their polygons, radii and
  /// reported velocities; mass then holds (M, M, I) per body. Null for particle scenes.
  std::shared_ptr<const RigidBodies> rigid_bodies;
  /// Per particle: the radius that collisions see and pictures draw.
  std::vector<double> particle_radius;
  std::vector<Edge> edges;
  /// Per edge: the radius of the capsule that collisions see and pictures draw.
  std::vector<double> edge_radius;
  /// Per edge, false for the edges of meshes: springs that are drawn but are no collision
  /// capsules (a cloth's bending springs pass through its vertices). Edges past its end collide.
  std::vector<bool> edge_collides;
  std::vector<HalfPlane> half_planes;          ///< solid obstacles, numbered in file order
  std::vector<Sphere> spheres;                 ///< static balls (3D), numbered in file order
  CollisionSettings collisions;                ///< how contact is handled (docs/collisions.md)
  std::vector<std::unique_ptr<Force>> forces;  ///< summed in this order
  IntegratorSettings integrator;
  double duration = 0.0;  ///< simulated seconds

  int num_particles() const { return static_cast<int>(fixed.size()); }
  int num_dofs() const { return dim * num_particles(); }
  bool is_fixed_dof(int dof) const { return fixed[dof / dim]; }
  bool has_fixed_particles() const;
  /// True when edge e is a collision capsule (edge_collides).
  bool is_colliding_edge(int e) const {
    return e >= static_cast<int>(edge_collides.size()) || edge_collides[e];
  }
  /// ceil(duration / dt) in double precision (4.0 / 0.01 gives 400), the number of steps a run
  /// takes, saturated at kMaxStepCount: a count beyond it (or an infinite one, from a dt so small
  /// that duration / dt overflows) is refused with a message by check_step_count
  /// (core/limits.h) before a run starts.
  std::int64_t num_steps() const;

  /// 2^62: more steps than any run takes, and safe from int64 overflow when frames are counted
  /// (steps + 1).
  static constexpr std::int64_t kMaxStepCount = std::int64_t{1} << 62;
};

}  // namespace fosssim
