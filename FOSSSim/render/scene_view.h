#pragma once
// A running scene as a viewer sees it: camera, picture size and trails.

#include "core/scene.h"
#include "core/state.h"
#include "render/camera.h"
#include "render/drawing.h"
#include "render/path_history.h"

namespace fosssim {

/// Follows a run of `scene` for a viewer (the window, picture and movie outputs): starts with
/// the scene's initial camera and records the trails as states arrive. The scene must outlive it.
class SceneView {
 public:
  /// width, height: picture size in pixels. The camera is the scene's viewport or is fitted to
  /// `initial`, whose positions start the trails.
  SceneView(const Scene& scene, const State& initial, int width, int height);

  /// Records a new state's positions in the trails; call once per step.
  void record(const State& state);
  /// The drawing of `state` as this view sees it.
  Drawing compose(const State& state, const Overlay& overlay = {}) const;

  /// Fits the camera to `state` (the window's `c` key); a viewport is not re-applied.
  void recenter(const State& state);
  /// Forgets the trails and starts them again at `state`.
  void restart_trails(const State& state);
  /// Changes the picture size, keeping the camera.
  void resize(int width, int height);

  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const Scene& scene_;
  int width_, height_;
  Camera camera_;
  PathHistory paths_;
};

}  // namespace fosssim
