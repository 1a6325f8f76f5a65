#include "pictures/image.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

Color Image::color_at(int x, int y) const {
  const std::uint32_t p = at(x, y);
  return {((p >> 16) & 0xff) / 255.0, ((p >> 8) & 0xff) / 255.0, (p & 0xff) / 255.0};
}

double color_distance(const Color& a, const Color& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

}  // namespace fosssim
