#include "viewer/particle_grab.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rigid/rigid_bodies.h"
#include "render/picking.h"

namespace fosssim {

namespace {

Eigen::Vector3d position(const State& state, int dim, int particle) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  x.head(dim) = state.q.segment(dim * particle, dim);
  return x;
}

}  // namespace

double suggest_drag_stiffness(const SceneModel& model, int particle) {
  const double h = model.integrator.dt;
  return model.mass[model.dim * particle] / (h * h);
}

double drag_stiffness(const SceneModel& model, int particle) {
  if (!model.integrator.method->properties.implicit) return suggest_drag_stiffness(model, particle);
  double free_mass = 0.0;
  for (int p = 0; p < model.num_particles(); ++p) {
    if (!model.fixed[p]) free_mass += model.mass[model.dim * p];
  }
  const double h = model.integrator.dt;
  return std::max(free_mass, model.mass[model.dim * particle]) / (h * h);
}

ParticleGrab::ParticleGrab(const Scene& scene) : model_(scene.model), spring_(scene.model.dim) {
  const auto& radii = scene.model.particle_radius;
  if (!radii.empty()) largest_radius_ = *std::max_element(radii.begin(), radii.end());
}

double rigid_drag_stiffness(const SceneModel& model, int body, const Vec<2>& arm) {
  const RigidBody& b = model.rigid_bodies->bodies.at(body);
  const double h = model.integrator.dt;
  const double felt_mass = 1.0 / (1.0 / b.mass + arm.squaredNorm() / b.inertia);
  return felt_mass / (h * h);
}

namespace {

/// Distance from p to the segment from a to b.
double segment_distance(const Vec<2>& p, const Vec<2>& a, const Vec<2>& b) {
  const Vec<2> e = b - a;
  const double length2 = e.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(e) / length2, 0.0, 1.0) : 0.0;
  return (a + t * e - p).norm();
}

}  // namespace

std::optional<int> pick_rigid_body(const SceneModel& model, const State& state,
                                   const Vec<2>& point, double slack) {
  const RigidBodies& bodies = *model.rigid_bodies;
  std::optional<int> nearest;
  double nearest_gap = std::numeric_limits<double>::infinity();
  for (int b = bodies.size() - 1; b >= 0; --b) {
    const RigidBody& body = bodies.bodies[b];
    const int n = body.num_vertices();
    bool inside = false;  // crossing test (even–odd), whatever the hull's orientation
    double distance = std::numeric_limits<double>::infinity();
    for (int k = 0; k < n; ++k) {
      const Vec<2> a = world_vertex(body, state.q, b, k);
      const Vec<2> c = world_vertex(body, state.q, b, (k + 1) % n);
      if ((a.y() > point.y()) != (c.y() > point.y()) &&
          point.x() < a.x() + (point.y() - a.y()) * (c.x() - a.x()) / (c.y() - a.y())) {
        inside = !inside;
      }
      distance = std::min(distance, segment_distance(point, a, c));
    }
    if (n >= 3 && inside) return b;  // the topmost body containing the point
    const double gap = distance - body.radius - slack;
    if (gap <= 0.0 && gap < nearest_gap) {
      nearest_gap = gap;
      nearest = b;
    }
  }
  return nearest;
}

const Force& ParticleGrab::interaction_force() const {
  if (model_.rigid_bodies) return rigid_spring_;
  return spring_;
}

bool ParticleGrab::press_rigid(const SceneView& view, const State& state, double px, double py) {
  const auto hit = drag_target(view.ray_through(px, py), Eigen::Vector3d::Zero(),
                               Eigen::Vector3d::UnitZ());
  if (!hit) return false;
  const Vec<2> point = hit->head<2>();
  const double slack = kPickPixels * view.units_per_pixel_at(Eigen::Vector3d::Zero());
  const std::optional<int> picked = pick_rigid_body(model_, state, point, slack);
  if (!picked || model_.fixed[*picked]) return false;
  const Vec<2> arm = point - body_center(state.q, *picked);
  const double theta = body_angle(state.q, *picked);
  // The grabbed point in body space: R(θ)ᵀ arm.
  const Vec<2> body_point(std::cos(theta) * arm.x() + std::sin(theta) * arm.y(),
                          -std::sin(theta) * arm.x() + std::cos(theta) * arm.y());
  plane_point_ = Eigen::Vector3d(point.x(), point.y(), 0.0);
  plane_normal_ = Eigen::Vector3d::UnitZ();
  offset_ = Eigen::Vector3d::Zero();  // the point under the cursor is the one pulled
  rigid_spring_.grab(*picked, body_point, point, rigid_drag_stiffness(model_, *picked, arm));
  return true;
}

bool ParticleGrab::press(const SceneView& view, const State& state, double px, double py) {
  if (model_.rigid_bodies) return press_rigid(view, state, px, py);
  const int dim = model_.dim;
  const Ray ray = view.ray_through(px, py);
  const Eigen::Vector3d focus = view.is_3d() ? view.orbit_camera().target : Eigen::Vector3d::Zero();
  const double radius = std::max(kPickPixels * view.units_per_pixel_at(focus), largest_radius_);
  const std::optional<int> picked = pick_particle(state.q, dim, ray, radius);
  if (!picked || model_.fixed[*picked]) return false;
  plane_point_ = position(state, dim, *picked);
  plane_normal_ = -view.view_direction();
  const auto hit = drag_target(ray, plane_point_, plane_normal_);
  offset_ = hit ? Eigen::Vector3d(plane_point_ - *hit) : Eigen::Vector3d::Zero();
  spring_.grab(*picked, plane_point_, drag_stiffness(model_, *picked));
  return true;
}

void ParticleGrab::move(const SceneView& view, double px, double py) {
  if (!active()) return;
  if (const auto hit = drag_target(view.ray_through(px, py), plane_point_, plane_normal_)) {
    spring_.move_target(*hit + offset_);
    rigid_spring_.move_target(hit->head<2>());
  }
}

std::optional<DragGuide> ParticleGrab::guide() const {
  if (rigid_spring_.active()) {
    const Vec<2>& t = rigid_spring_.target();
    return DragGuide{rigid_spring_.body(), Eigen::Vector3d(t.x(), t.y(), 0.0),
                     rigid_spring_.body_point()};
  }
  if (!active()) return std::nullopt;
  return DragGuide{spring_.particle(), spring_.target(), std::nullopt};
}

}  // namespace fosssim
