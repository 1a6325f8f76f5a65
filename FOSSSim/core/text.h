#pragma once
// Number formatting for messages: the shortest text that reads back to the same double.

#include <charconv>
#include <string>

#if defined(__EMSCRIPTEN__)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#endif

namespace fosssim {

#if defined(__EMSCRIPTEN__)
/// std::to_chars(double) as the standard defines it, for Emscripten 3.1.6's C++ library, which
/// lacks it: the fewest significant digits that read back to `value` (the correctly rounded
/// ones, as printf gives them), then fixed or scientific notation, whichever is shorter, fixed
/// on a tie ("1e+20", "1e-05", "0.001", "123.5").
inline std::string shortest_text(double value) {
  if (!std::isfinite(value)) return value != value ? "nan" : value < 0 ? "-inf" : "inf";
  char buffer[400];  // the fixed form of DBL_MAX has 309 digits
  int digits = 1;
  for (; digits < 17; ++digits) {
    std::snprintf(buffer, sizeof(buffer), "%.*e", digits - 1, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  std::snprintf(buffer, sizeof(buffer), "%.*e", digits - 1, value);
  const std::string scientific(buffer);  // "1e+20", "1.5e-05", as std::to_chars writes them
  const std::size_t e = scientific.find('e');
  const int exponent = std::atoi(scientific.c_str() + e + 1);
  const int decimals = std::max(0, digits - 1 - exponent);
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  const std::string fixed(buffer);
  return fixed.size() <= scientific.size() ? fixed : scientific;
}
#endif

inline std::string to_text(double value) {
#if defined(__EMSCRIPTEN__)
  return shortest_text(value);
#else
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
#endif
}

}  // namespace fosssim
