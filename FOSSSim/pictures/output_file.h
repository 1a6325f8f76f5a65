#pragma once
// Outputs appear whole or not at all: written under a temporary name, then renamed.

#include <string>

namespace fosssim {

/// The name an output is written under before it is complete: "<path>.partial".
std::string partial_name(const std::string& path);

/// Renames a finished `temporary` file to `path`, replacing any earlier file. On failure
/// removes `temporary` and throws std::runtime_error naming both paths and the reason.
void move_into_place(const std::string& temporary, const std::string& path);

}  // namespace fosssim
