#include "render/orbit_camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace fosssim {

namespace {

/// The fitted box fills 1 / 1.3 of the half picture: a little more room than the 2D camera's
/// 1 / 1.2, since meshes sag and swing out of their first box.
constexpr double kFitMargin = 1.0 / 1.3;
/// The near plane, as a fraction of the camera's distance.
constexpr double kNearFraction = 0.01;
/// Parallel-view rays start this many camera distances behind the eye.
constexpr double kParallelRayBack = 1e3;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

/// The camera's unit right vector: forward × y, which for forward = -orbit_direction is
/// (cos yaw, 0, -sin yaw) whatever the pitch.
Eigen::Vector3d right_vector(double yaw) { return {std::cos(yaw), 0.0, -std::sin(yaw)}; }

double clamp_pitch(double pitch) {
  const double limit = radians(kMaxPitchDegrees);
  return std::clamp(pitch, -limit, limit);
}

/// World units per pixel at the target's depth (the same in both projections).
double units_per_pixel_at_target(const OrbitCamera& camera, int height) {
  return 2.0 * camera.distance * std::tan(0.5 * camera.fov) / height;
}

}  // namespace

Eigen::Vector3d orbit_direction(double yaw, double pitch) {
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

OrbitProjection::OrbitProjection(const OrbitCamera& camera, int width, int height)
    : width_(width), height_(height) {
  const Eigen::Vector3d back = orbit_direction(camera.yaw, camera.pitch);
  eye_ = camera.target + camera.distance * back;
  forward_ = -back;
  right_ = right_vector(camera.yaw);
  up_ = right_.cross(forward_);
  focal_ = 0.5 * height / std::tan(0.5 * camera.fov);
  distance_ = camera.distance;
  near_ = kNearFraction * camera.distance;
  ortho_pixels_per_unit_ =
      camera.projection == Projection::kOrthographic ? focal_ / camera.distance : 0.0;
}

ProjectedPoint OrbitProjection::project(const Eigen::Vector3d& point) const {
  const Eigen::Vector3d v = point - eye_;
  const double x = v.dot(right_), y = v.dot(up_), z = v.dot(forward_);
  ProjectedPoint result;
  result.depth = z;
  if (ortho_pixels_per_unit_ > 0.0) {
    result.pixel = {0.5 * width_ + ortho_pixels_per_unit_ * x,
                    0.5 * height_ - ortho_pixels_per_unit_ * y};
    return result;
  }
  if (z < near_) {
    result.visible = false;
    return result;
  }
  result.pixel = {0.5 * width_ + focal_ * x / z, 0.5 * height_ - focal_ * y / z};
  return result;
}

double OrbitProjection::pixels_per_unit(double depth) const {
  if (ortho_pixels_per_unit_ > 0.0) return ortho_pixels_per_unit_;
  return focal_ / std::max(depth, near_);
}

Ray OrbitProjection::ray_through(double px, double py) const {
  const double a = px - 0.5 * width_, b = 0.5 * height_ - py;
  Ray ray;
  if (ortho_pixels_per_unit_ > 0.0) {
    ray.origin = eye_ + (a * right_ + b * up_) / ortho_pixels_per_unit_ -
                 kParallelRayBack * distance_ * forward_;
    ray.direction = forward_;
  } else {
    ray.origin = eye_;
    ray.direction = forward_ + (a * right_ + b * up_) / focal_;
  }
  return ray;
}

double fit_distance(const OrbitCamera& camera, const Eigen::Vector3d& low,
                    const Eigen::Vector3d& high, int width, int height) {
  const OrbitProjection axes(camera, width, height);
  const double tan_half = std::tan(0.5 * camera.fov);
  const double height_over_width = static_cast<double>(height) / width;
  double needed = 0.0;  // perspective: distance; parallel: visible half height at the target
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d c((corner & 1) ? high.x() : low.x(), (corner & 2) ? high.y() : low.y(),
                            (corner & 4) ? high.z() : low.z());
    const Eigen::Vector3d v = c - camera.target;
    const double x = std::abs(v.dot(axes.right())), y = std::abs(v.dot(axes.up()));
    const double z = v.dot(axes.forward());  // positive: farther than the target
    if (camera.projection == Projection::kOrthographic) {
      needed = std::max({needed, y / kFitMargin, x * height_over_width / kFitMargin});
    } else {
      // F|x| / (d + z) ≤ m W/2 with F = (H/2) / tan(fov/2), likewise for y, and the corner
      // in front of the near plane: d + z ≥ 0.01 d.
      needed = std::max({needed, x * height_over_width / (kFitMargin * tan_half) - z,
                         y / (kFitMargin * tan_half) - z, -z / (1.0 - kNearFraction)});
    }
  }
  if (!(needed > 0.0)) return 1.0 / tan_half;  // a single point: half height 1 at the target
  return camera.projection == Projection::kOrthographic ? needed / tan_half : needed;
}

void fit_orbit_camera(OrbitCamera& camera, const Vector& q, int dim, int width, int height) {
  const auto [low, high] = compute_bounding_box(q, dim);
  camera.target = 0.5 * (low + high);
  camera.distance = fit_distance(camera, low, high, width, height);
}

OrbitCamera initial_orbit_camera(const Scene& scene, const State& state, int width, int height) {
  const Appearance& look = scene.appearance;
  const int dim = scene.model.dim;
  OrbitCamera camera;
  camera.yaw = radians(kDefaultYawDegrees);
  camera.pitch = radians(kDefaultPitchDegrees);
  if (look.camera3d) {
    const OrbitViewSettings& view = *look.camera3d;
    if (view.yaw) camera.yaw = radians(*view.yaw);
    if (view.pitch) camera.pitch = clamp_pitch(radians(*view.pitch));
    if (view.fov) camera.fov = radians(*view.fov);
    if (view.orthographic) camera.projection = Projection::kOrthographic;
    const auto [low, high] = compute_bounding_box(state.q, dim);
    camera.target = view.target ? Eigen::Vector3d(view.target->data()) : 0.5 * (low + high);
    camera.distance =
        view.distance ? *view.distance : fit_distance(camera, low, high, width, height);
    return camera;
  }
  if (look.viewport) {
    const auto [low, high] = compute_bounding_box(state.q, dim);
    camera.yaw = camera.pitch = 0.0;
    camera.projection = Projection::kOrthographic;
    camera.target = {look.viewport->cx, look.viewport->cy, 0.5 * (low.z() + high.z())};
    camera.distance = look.viewport->size / std::tan(0.5 * camera.fov);
    return camera;
  }
  fit_orbit_camera(camera, state.q, dim, width, height);
  return camera;
}

void turn_orbit_camera(OrbitCamera& camera, double dx, double dy, int height) {
  const double radians_per_pixel = std::numbers::pi / height;
  camera.yaw -= dx * radians_per_pixel;
  camera.pitch = clamp_pitch(camera.pitch + dy * radians_per_pixel);
}

void pan_orbit_camera(OrbitCamera& camera, double dx, double dy, int height) {
  const Eigen::Vector3d right = right_vector(camera.yaw);
  const Eigen::Vector3d up = right.cross(-orbit_direction(camera.yaw, camera.pitch));
  camera.target -= (dx * right - dy * up) * units_per_pixel_at_target(camera, height);
}

void zoom_orbit_camera(OrbitCamera& camera, double factor) { camera.distance *= factor; }

}  // namespace fosssim
