#pragma once
// Counting a colour's pixels in a picture, for tests of what a picture shows.

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

}  // namespace fosssim::testing
