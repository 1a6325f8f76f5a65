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

std::array<Eigen::Vector3d, 2> compute_bounding_box(const Vector& q, int dim) {
  const int n = static_cast<int>(q.size()) / dim;
  if (n == 0) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  Eigen::Vector3d low = Eigen::Vector3d::Zero();
  low.head(dim) = q.head(dim);
  Eigen::Vector3d high = low;
  for (int p = 1; p < n; ++p) {
    for (int c = 0; c < dim; ++c) {
      low[c] = std::min(low[c], q[dim * p + c]);
      high[c] = std::max(high[c], q[dim * p + c]);
    }
  }
  return {low, high};
}

Camera fit_camera(const Vector& q, int dim, int width, int height) {
  // No particles: a zero box, hence the default camera (centre 0, scale 1).
  const auto [low, high] = compute_bounding_box(q, dim);
  Camera camera;
  camera.cx = 0.5 * (low.x() + high.x());
  camera.cy = 0.5 * (low.y() + high.y());
  const double height_over_width = static_cast<double>(height) / width;
  camera.scale =
      1.2 * std::max(0.5 * (high.y() - low.y()), 0.5 * (high.x() - low.x()) * height_over_width);
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
