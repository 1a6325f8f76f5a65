#include "render/shading.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace fosssim {

namespace {
constexpr Color kBackTint{0.5, 0.5, 0.5};
constexpr double kBackMix = 1.0 / 3.0;
}  // namespace

Color shade_lambert(const Color& base, const Eigen::Vector3d& normal, const Lighting& light) {
  const double length = normal.norm();
  double amount = light.ambient;
  if (length > 0.0) {
    const Eigen::Vector3d n = normal / length;
    amount += light.key * std::max(0.0, n.dot(light.to_key)) +
              light.head * std::max(0.0, n.dot(light.to_eye));
  }
  auto channel = [amount](double c) { return std::clamp(c * amount, 0.0, 1.0); };
  return {channel(base.r), channel(base.g), channel(base.b)};
}

Color back_side_color(const Color& front) {
  auto mix = [](double c, double tint) { return (1.0 - kBackMix) * c + kBackMix * tint; };
  return {mix(front.r, kBackTint.r), mix(front.g, kBackTint.g), mix(front.b, kBackTint.b)};
}

Color shade_triangle(const Color& front, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const Eigen::Vector3d& c, const Eigen::Vector3d& view, Lighting light,
                     BackSide back) {
  const double length = view.norm();
  if (length > 0.0) light.to_eye = -view / length;
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  if (normal.dot(view) > 0.0) {
    const Color seen = back == BackSide::kTinted ? back_side_color(front) : front;
    return shade_lambert(seen, -normal, light);
  }
  return shade_lambert(front, normal, light);
}

Lighting camera_lighting(const Eigen::Vector3d& right, const Eigen::Vector3d& up,
                         const Eigen::Vector3d& forward) {
  Lighting light;
  light.to_key = (-0.3 * right + 0.8 * up - 0.5 * forward).normalized();
  light.to_eye = -forward;
  return light;
}

}  // namespace fosssim
