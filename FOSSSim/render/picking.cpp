#include "render/picking.h"

#include <limits>

namespace fosssim {

std::optional<int> pick_particle(const Vector& q, int dim, const Ray& ray, double radius) {
  const double length = ray.direction.norm();
  if (length == 0.0) return std::nullopt;
  const Eigen::Vector3d u = ray.direction / length;
  std::optional<int> best;
  double best_t = std::numeric_limits<double>::infinity();
  double best_off = best_t;
  const int n = static_cast<int>(q.size()) / dim;
  for (int p = 0; p < n; ++p) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    x.head(dim) = q.segment(dim * p, dim);
    const Eigen::Vector3d w = x - ray.origin;
    const double t = w.dot(u);
    if (t < 0.0) continue;
    const double off = (w - t * u).norm();
    if (off <= radius && (t < best_t || (t == best_t && off < best_off))) {
      best_t = t;
      best_off = off;
      best = p;
    }
  }
  return best;
}

std::optional<Eigen::Vector3d> drag_target(const Ray& ray, const Eigen::Vector3d& plane_point,
                                           const Eigen::Vector3d& plane_normal) {
  const double denominator = plane_normal.dot(ray.direction);
  if (denominator == 0.0) return std::nullopt;
  const double t = plane_normal.dot(plane_point - ray.origin) / denominator;
  if (t < 0.0) return std::nullopt;
  return Eigen::Vector3d(ray.origin + t * ray.direction);
}

}  // namespace fosssim
