#pragma once
// The 2D orthographic camera of the window and the pictures (docs/viewing.md, 'Camera').

#include <Eigen/Core>
#include <array>

#include "core/scene.h"
#include "core/state.h"

namespace fosssim {

/// A point in world units or in pixels, depending on context.
struct Point2 {
  double x = 0.0, y = 0.0;
};

/// An orthographic view of the x-y plane: the visible rectangle is centred on (cx, cy), is
/// 2·scale tall and 2·scale·(width/height) wide. `scale` is the course's "scale factor" and the
/// `size` of a scene's <viewport>. 3D scenes are seen along -z.
struct Camera {
  double cx = 0.0, cy = 0.0;
  double scale = 1.0;  ///< half the visible height, world units (> 0)
};

/// A camera looking at a picture of width × height pixels: maps world points to pixels, whose
/// origin is the top-left corner of the picture with y growing downwards.
class PixelMapping {
 public:
  PixelMapping(const Camera& camera, int width, int height);

  Point2 to_pixel(double x, double y) const;
  Point2 to_world(double px, double py) const;
  /// Pixels per world unit (the same horizontally and vertically).
  double pixels_per_unit() const { return pixels_per_unit_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  double left_, top_, pixels_per_unit_;
  int width_, height_;
};

/// The bounding box of the particle centres (q interleaved, `dim` per particle, z = 0 in 2D):
/// {low, high}; both zero when there are no particles.
std::array<Eigen::Vector3d, 2> compute_bounding_box(const Vector& q, int dim);

/// The course's fitted camera: centred on the bounding box of the particle centres, with
/// scale = 1.2 · max(half height, half width · height/width), so the box fits with a margin
/// whatever the picture's aspect. A box of zero size (one particle, or none) gets scale 1.
/// q: interleaved positions with `dim` coordinates per particle.
Camera fit_camera(const Vector& q, int dim, int width, int height);

/// The scene's <viewport> if it has one, else the camera fitted to `state`.
Camera initial_camera(const Scene& scene, const State& state, int width, int height);

/// Multiplies the visible height by `factor` (> 1 zooms out), keeping the centre.
void zoom_camera(Camera& camera, double factor);

/// Moves the view as if its picture were dragged by (dx, dy) pixels (y down): the world point
/// under the cursor stays under the cursor.
void drag_camera(Camera& camera, double dx, double dy, int height);

}  // namespace fosssim
