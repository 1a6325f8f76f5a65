#include "viewer/particle_grab.h"

#include <algorithm>

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

bool ParticleGrab::press(const SceneView& view, const State& state, double px, double py) {
  // A rigid body's coordinates are (x, y, θ): the drag spring, written for particles, would
  // pull its angle like a third coordinate. Dragging bodies is not supported yet.
  if (model_.rigid_bodies) return false;
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
  }
}

std::optional<DragGuide> ParticleGrab::guide() const {
  if (!active()) return std::nullopt;
  return DragGuide{spring_.particle(), spring_.target()};
}

}  // namespace fosssim
