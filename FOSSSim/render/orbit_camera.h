#pragma once
// The 3D camera of the window and the pictures: an orbit camera around a target point, seen in
// perspective or in parallel projection, y up.

#include <Eigen/Core>

#include "core/scene.h"
#include "core/state.h"
#include "render/camera.h"
#include "render/picking.h"

namespace fosssim {

enum class Projection { kPerspective, kOrthographic };

/// The default 3D view: a three-quarter view from the front right, a little from above.
inline constexpr double kDefaultYawDegrees = 30.0;
inline constexpr double kDefaultPitchDegrees = 20.0;
inline constexpr double kDefaultFovDegrees = 30.0;
/// Pitch stays within ±89° so that "up" is always defined.
inline constexpr double kMaxPitchDegrees = 89.0;

/// An orbit camera. The eye is at target + distance · (cos p sin y, sin p, cos p cos y) for yaw
/// y and pitch p and looks at the target with +y up: yaw 0, pitch 0 looks along -z with x to the
/// right, as the 2D camera does; positive yaw moves the eye toward +x, positive pitch above.
/// In parallel projection (kOrthographic) the visible height at any depth is the one the
/// perspective camera has at the target: 2 · distance · tan(fov / 2).
struct OrbitCamera {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< world units
  double yaw = 0.0;                                  ///< radians
  double pitch = 0.0;                                ///< radians, |pitch| ≤ kMaxPitchDegrees
  double distance = 1.0;                             ///< eye to target, world units (> 0)
  double fov = kDefaultFovDegrees * 0.017453292519943295;  ///< vertical, radians, in (0, π)
  Projection projection = Projection::kPerspective;
};

/// A world point as the camera sees it.
struct ProjectedPoint {
  Point2 pixel;         ///< origin top-left, y down
  double depth = 0.0;   ///< distance in front of the eye along the view direction, world units
  bool visible = true;  ///< false when it is behind the near plane (perspective only)
};

/// The camera looking at a picture of width × height pixels: world points to pixels and
/// pixels to rays. Perspective: a point at view coordinates (x right, y up, depth z) goes to
/// pixel (W/2 + F x / z, H/2 - F y / z) with the focal length F = (H/2) / tan(fov/2) in pixels;
/// parallel: (W/2 + F x / d, H/2 - F y / d) with d the camera's distance.
class OrbitProjection {
 public:
  OrbitProjection(const OrbitCamera& camera, int width, int height);

  ProjectedPoint project(const Eigen::Vector3d& point) const;
  /// Pixels per world unit of a length seen square-on at `depth` (constant in parallel view).
  double pixels_per_unit(double depth) const;
  /// The ray from the eye through pixel (px, py); in parallel view it starts far behind the
  /// eye, so that everything the picture shows lies ahead of it.
  Ray ray_through(double px, double py) const;
  /// Depth of a world point along the view direction (negative behind the eye).
  double depth_of(const Eigen::Vector3d& point) const { return (point - eye_).dot(forward_); }

  const Eigen::Vector3d& eye() const { return eye_; }
  /// The unit view direction, from the eye toward the target.
  const Eigen::Vector3d& forward() const { return forward_; }
  const Eigen::Vector3d& right() const { return right_; }
  const Eigen::Vector3d& up() const { return up_; }
  /// Points nearer than this are not drawn (perspective): 1 % of the distance.
  double near_depth() const { return near_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Eigen::Vector3d eye_, forward_, right_, up_;
  double focal_;  ///< pixels
  double distance_, near_;
  double ortho_pixels_per_unit_;  ///< 0 in perspective
  int width_, height_;
};

/// The unit vector from the target toward the eye for a yaw and pitch (radians).
Eigen::Vector3d orbit_direction(double yaw, double pitch);

/// The distance at which `camera` (with its orientation, target, field of view and projection)
/// shows every corner of the box [low, high] inside the picture with a margin: each corner's
/// projection stays within 1 / 1.3 of the half width and half height from the centre. An empty box
/// (a single point) gets a visible half height of 1 at the target.
double fit_distance(const OrbitCamera& camera, const Eigen::Vector3d& low,
                    const Eigen::Vector3d& high, int width, int height);

/// Sets the target to the centre of the particles' bounding box and the distance to
/// fit_distance, keeping the camera's angles, field of view and projection.
void fit_orbit_camera(OrbitCamera& camera, const Vector& q, int dim, int width, int height);

/// The camera a 3D scene's pictures start with. With a <camera3d> (or --view): its angles,
/// field of view and projection, its target or the box centre, its distance or the fitted one.
/// Otherwise with a <viewport cx cy size>: the 2D camera's view, parallel along -z centred on
/// (cx, cy) with half height `size`. Otherwise the default three-quarter view, fitted.
OrbitCamera initial_orbit_camera(const Scene& scene, const State& state, int width, int height);

/// Turns the view as if the scene were dragged by (dx, dy) pixels: a drag across the whole
/// picture height turns it by 180°. Dragging right turns the scene right (the eye moves left),
/// dragging down tilts its top toward the viewer (the eye moves up); pitch stays within ±89°.
void turn_orbit_camera(OrbitCamera& camera, double dx, double dy, int height);

/// Moves the target across the view so that points at the target's depth follow a drag of
/// (dx, dy) pixels (y down).
void pan_orbit_camera(OrbitCamera& camera, double dx, double dy, int height);

/// Multiplies the distance by `factor` (> 1 zooms out), keeping the target.
void zoom_orbit_camera(OrbitCamera& camera, double factor);

}  // namespace fosssim
