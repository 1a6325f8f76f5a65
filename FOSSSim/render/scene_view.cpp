#include "render/scene_view.h"

namespace fosssim {

namespace {
/// `initial` with the positions `frame` when given: what the first camera is fitted to.
State framing_state(const State& initial, const Vector* frame) {
  State framing = initial;
  if (frame) framing.q = *frame;
  return framing;
}
}  // namespace

SceneView::SceneView(const Scene& scene, const State& initial, int width, int height,
                     const Vector* frame)
    : scene_(scene),
      width_(width),
      height_(height),
      camera_(initial_camera(scene, framing_state(initial, frame), width, height)),
      paths_(scene) {
  if (scene.model.dim == 3 && !scene.model.rigid_bodies) {  // bodies are planar: (x, y, θ)
    orbit_ = initial_orbit_camera(scene, framing_state(initial, frame), width, height);
    parts_ = compute_scene_parts_3d(scene);
  }
  paths_.record(initial.q, scene.model.dim);
}

void SceneView::record(const State& state) { paths_.record(state.q, scene_.model.dim); }

Drawing SceneView::compose(const State& state, const Overlay& overlay) const {
  Overlay with_colors = overlay;
  with_colors.elements = element_colors_;
  if (orbit_) {
    return compose_drawing_3d(scene_, parts_, state, paths_, *orbit_, width_, height_, with_colors);
  }
  return compose_drawing(scene_, state, paths_, camera_, width_, height_, with_colors);
}

void SceneView::recenter(const State& state) {
  if (orbit_) {
    fit_orbit_camera(*orbit_, state.q, scene_.model.dim, width_, height_);
  } else {
    camera_ = fit_camera(state.q, scene_.model.dim, width_, height_);
  }
}

void SceneView::restart_trails(const State& state) {
  paths_.clear();
  paths_.record(state.q, scene_.model.dim);
}

void SceneView::resize(int width, int height) {
  width_ = width;
  height_ = height;
}

void SceneView::pan(double dx, double dy) {
  if (orbit_) {
    pan_orbit_camera(*orbit_, dx, dy, height_);
  } else {
    drag_camera(camera_, dx, dy, height_);
  }
}

void SceneView::zoom(double factor) {
  if (orbit_) {
    zoom_orbit_camera(*orbit_, factor);
  } else {
    zoom_camera(camera_, factor);
  }
}

void SceneView::orbit(double dx, double dy) {
  if (orbit_) turn_orbit_camera(*orbit_, dx, dy, height_);
}

Ray SceneView::ray_through(double px, double py) const {
  if (orbit_) return OrbitProjection(*orbit_, width_, height_).ray_through(px, py);
  const Point2 world = PixelMapping(camera_, width_, height_).to_world(px, py);
  return Ray{Eigen::Vector3d(world.x, world.y, 1.0), -Eigen::Vector3d::UnitZ()};
}

Eigen::Vector3d SceneView::view_direction() const {
  if (orbit_) return OrbitProjection(*orbit_, width_, height_).forward();
  return -Eigen::Vector3d::UnitZ();
}

double SceneView::units_per_pixel_at(const Eigen::Vector3d& point) const {
  if (orbit_) {
    const OrbitProjection projection(*orbit_, width_, height_);
    return 1.0 / projection.pixels_per_unit(projection.depth_of(point));
  }
  return 1.0 / PixelMapping(camera_, width_, height_).pixels_per_unit();
}

}  // namespace fosssim
