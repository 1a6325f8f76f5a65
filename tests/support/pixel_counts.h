#pragma once
// Counting a colour's pixels in a picture, for tests of what a picture shows.

#include <algorithm>
#include <cmath>

#include "pictures/image.h"

namespace fosssim::testing {

/// Number of pixels within `tolerance` of `color`.
inline int count_color(const Image& image, const Color& color, double tolerance = 0.08) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x)
      n += color_distance(image.color_at(x, y), color) < tolerance;
  }
  return n;
}

/// How much of `color` the pixel `shown` has over a white background: the a in [0, 1] for which
/// shown = (1 - a) · white + a · color within `tolerance` in every component, or 0 when no a
/// fits (another colour). An anti-aliased line shows its colour with a < 1 where it covers a
/// pixel only in part.
inline double coverage(const Color& shown, const Color& color, double tolerance = 0.06) {
  const double components[3][2] = {{shown.r, color.r}, {shown.g, color.g}, {shown.b, color.b}};
  // a from the component where the colour differs most from white, then checked on all three.
  double a = 0.0, largest = 0.0;
  for (const auto& [s, c] : components) {
    if (1.0 - c > largest) largest = 1.0 - c, a = (1.0 - s) / (1.0 - c);
  }
  a = std::clamp(a, 0.0, 1.0);
  for (const auto& [s, c] : components) {
    if (std::abs((1.0 - a) + a * c - s) > tolerance) return 0.0;
  }
  return a;
}

}  // namespace fosssim::testing
