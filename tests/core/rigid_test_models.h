#pragma once
// Rigid-body models built in code for the core tests (the loader builds them from files).

#include <memory>
#include <vector>

#include "core/rigid/rigid_bodies.h"
#include "core/scene_model.h"
#include "core/state.h"

namespace fosssim::testing {

/// A body to build: hull points in world coordinates with their masses, and its velocity.
struct BodySpec {
  std::vector<Vec2> points;
  std::vector<double> masses;
  Vec2 velocity = Vec2::Zero();
  double omega = 0.0;
  bool fixed = false;
  double radius = 0.1;
};

/// A rigid-body model as the loader makes it (dim 3, masses (M, M, I), fixed bodies at rest in
/// the state with their declared velocity reported), with no forces yet, and its initial state.
inline std::pair<SceneModel, State> make_rigid_model(const std::vector<BodySpec>& specs) {
  SceneModel model;
  State state;
  model.dim = kRigidBodyCoordinates;
  auto bodies = std::make_shared<RigidBodies>();
  const int n = static_cast<int>(specs.size());
  model.mass.resize(3 * n);
  state.q.resize(3 * n);
  state.v.resize(3 * n);
  for (int b = 0; b < n; ++b) {
    const BodySpec& spec = specs[b];
    const MassProperties mp = compute_mass_properties(spec.points, spec.masses);
    RigidBody body;
    body.mass = mp.mass;
    body.inertia = mp.inertia;
    body.initial_center = mp.center;
    for (const Vec2& p : spec.points) body.body_points.push_back(p - mp.center);
    body.radius = spec.radius;
    body.fixed = spec.fixed;
    if (spec.fixed) {
      body.reported_velocity = spec.velocity;
      body.reported_omega = spec.omega;
    }
    model.mass.segment<3>(3 * b) << mp.mass, mp.mass, mp.inertia;
    model.fixed.push_back(spec.fixed);
    model.particle_radius.push_back(spec.radius);
    state.q.segment<3>(3 * b) << mp.center.x(), mp.center.y(), 0.0;
    if (spec.fixed) {
      state.v.segment<3>(3 * b).setZero();
    } else {
      state.v.segment<3>(3 * b) << spec.velocity.x(), spec.velocity.y(), spec.omega;
    }
    bodies->bodies.push_back(std::move(body));
  }
  model.rigid_bodies = std::move(bodies);
  return {std::move(model), std::move(state)};
}

}  // namespace fosssim::testing
