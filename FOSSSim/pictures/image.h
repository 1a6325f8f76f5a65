#pragma once
// A picture in memory, as Cairo paints it.

#include <cstdint>
#include <vector>

#include "core/scene.h"

namespace fosssim {

/// width × height pixels, rows top to bottom, each pixel a native-endian 32-bit 0xAARRGGBB
/// (Cairo's CAIRO_FORMAT_ARGB32; our pictures are opaque, so alpha is 255). In memory on a
/// little-endian machine the bytes of a pixel are B, G, R, A.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint32_t> pixels;

  std::uint32_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// The colour of pixel (x, y), each component in [0, 1].
  Color color_at(int x, int y) const;
};

/// The largest difference of a colour component between two colours, in [0, 1].
double color_distance(const Color& a, const Color& b);

}  // namespace fosssim
