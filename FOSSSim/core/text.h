#pragma once
// Number formatting for messages: the shortest text that reads back to the same double.

#include <charconv>
#include <string>

namespace fosssim {

inline std::string to_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace fosssim
