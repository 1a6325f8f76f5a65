#pragma once
// A running scene as a viewer sees it: camera, picture size and trails.

#include <optional>

#include "core/scene.h"
#include "core/state.h"
#include "render/camera.h"
#include "render/drawing.h"
#include "render/drawing_3d.h"
#include "render/orbit_camera.h"
#include "render/path_history.h"
#include "render/picking.h"

namespace fosssim {

/// Follows a run of `scene` for a viewer (the window, picture and movie outputs): starts with
/// the scene's initial camera and records the trails as states arrive. 2D scenes are seen
/// through the 2D camera (camera.h), 3D scenes through an orbit camera
/// (initial_orbit_camera). The scene must outlive it.
class SceneView {
 public:
  /// width, height: picture size in pixels. The camera is the scene's viewport (2D) or
  /// <camera3d> where they fix it, and is otherwise fitted to the positions `frame` (interleaved
  /// like q; for instance the corners of the box a whole run covers) or, without them, to
  /// `initial`'s. `initial`'s positions start the trails.
  SceneView(const Scene& scene, const State& initial, int width, int height,
            const Vector* frame = nullptr);

  /// Records a new state's positions in the trails; call once per step.
  void record(const State& state);
  /// The drawing of `state` as this view sees it.
  Drawing compose(const State& state, const Overlay& overlay = {}) const;

  /// Fits the camera to `state` (the window's `c` key); a viewport is not re-applied. A 3D
  /// view keeps its angles.
  void recenter(const State& state);
  /// Forgets the trails and starts them again at `state`.
  void restart_trails(const State& state);
  /// Changes the picture size, keeping the camera.
  void resize(int width, int height);
  /// How elastic triangles and hinges are coloured in every drawing composed from now on
  /// (the overlay's own setting is replaced).
  void set_element_colors(const ElementColors& colors) { element_colors_ = colors; }
  const ElementColors& element_colors() const { return element_colors_; }

  int width() const { return width_; }
  int height() const { return height_; }
  /// True for 3D scenes, seen through orbit_camera().
  bool is_3d() const { return orbit_.has_value(); }
  /// The 2D camera (of 2D scenes).
  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  /// The 3D camera; only for is_3d().
  OrbitCamera& orbit_camera() { return *orbit_; }
  const OrbitCamera& orbit_camera() const { return *orbit_; }

  /// Moves the view so that the picture follows a drag of (dx, dy) pixels (y down); in 3D, at
  /// the depth of the orbit camera's target.
  void pan(double dx, double dy);
  /// Scales the visible height by `factor` (> 1 zooms out).
  void zoom(double factor);
  /// 3D: turns the orbit camera as for a drag of (dx, dy) pixels (turn_orbit_camera); 2D:
  /// nothing.
  void orbit(double dx, double dy);

  /// The ray through pixel (px, py) of the picture: in 2D from (x, y, 1) down the z axis.
  Ray ray_through(double px, double py) const;
  /// The unit direction the camera looks along (2D: -z).
  Eigen::Vector3d view_direction() const;
  /// World units per pixel for lengths at `point` seen square-on.
  double units_per_pixel_at(const Eigen::Vector3d& point) const;

 private:
  const Scene& scene_;
  int width_, height_;
  Camera camera_;
  std::optional<OrbitCamera> orbit_;
  SceneParts3D parts_;
  PathHistory paths_;
  ElementColors element_colors_;
};

}  // namespace fosssim
