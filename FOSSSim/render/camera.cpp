#include "render/camera.h"

#include <algorithm>

namespace fosssim {

PixelMapping::PixelMapping(const Camera& camera, int width, int height)
    : width_(width), height_(height) {
  pixels_per_unit_ = height / (2.0 * camera.scale);
  left_ = camera.cx - 0.5 * width / pixels_per_unit_;
  top_ = camera.cy + camera.scale;
}

Point2 PixelMapping::to_pixel(double x, double y) const {
  return {(x - left_) * pixels_per_unit_, (top_ - y) * pixels_per_unit_};
}

Point2 PixelMapping::to_world(double px, double py) const {
  return {left_ + px / pixels_per_unit_, top_ - py / pixels_per_unit_};
}

Camera fit_camera(const Vector& q, int dim, int width, int height) {
  const int n = static_cast<int>(q.size()) / dim;
  if (n == 0) return Camera{};
  double min_x = q[0], max_x = q[0], min_y = q[1], max_y = q[1];
  for (int p = 1; p < n; ++p) {
    min_x = std::min(min_x, q[dim * p]);
    max_x = std::max(max_x, q[dim * p]);
    min_y = std::min(min_y, q[dim * p + 1]);
    max_y = std::max(max_y, q[dim * p + 1]);
  }
  Camera camera;
  camera.cx = 0.5 * (min_x + max_x);
  camera.cy = 0.5 * (min_y + max_y);
  const double height_over_width = static_cast<double>(height) / width;
  camera.scale = 1.2 * std::max(0.5 * (max_y - min_y), 0.5 * (max_x - min_x) * height_over_width);
  if (!(camera.scale > 0.0)) camera.scale = 1.0;
  return camera;
}

Camera initial_camera(const Scene& scene, const State& state, int width, int height) {
  if (const auto& viewport = scene.appearance.viewport) {
    return Camera{viewport->cx, viewport->cy, viewport->size};
  }
  return fit_camera(state.q, scene.model.dim, width, height);
}

void zoom_camera(Camera& camera, double factor) { camera.scale *= factor; }

void drag_camera(Camera& camera, double dx, double dy, int height) {
  const double units_per_pixel = 2.0 * camera.scale / height;
  camera.cx -= dx * units_per_pixel;
  camera.cy += dy * units_per_pixel;
}

}  // namespace fosssim
