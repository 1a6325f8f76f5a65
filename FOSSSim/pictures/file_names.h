#pragma once
// What kind of file a user's output path names.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

namespace fosssim {

/// True when the extension of `path`'s file name (std::filesystem's: from its last dot, so
/// ".svg" alone has none) is `extension` ignoring case. `extension` is lower case with its dot,
/// e.g. ".mp4".
inline bool has_extension(const std::string& path, std::string_view extension) {
  const std::string found = std::filesystem::path(path).extension().string();
  return std::equal(
      found.begin(), found.end(), extension.begin(), extension.end(),
      [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

}  // namespace fosssim
