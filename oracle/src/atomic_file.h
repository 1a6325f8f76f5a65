#pragma once
// Report files appear whole or not at all.

#include <optional>
#include <string>

namespace fosssim {

/// Writes `content` to "<path>.partial" (creating missing parent folders), flushes it to disk
/// and renames it to `path`, so that a reader never sees half a report. Returns an error
/// message naming the file and the system's reason, or nothing on success.
std::optional<std::string> write_file_atomically(const std::string& path,
                                                 const std::string& content);

/// Reads a whole file; nothing when it cannot be read.
std::optional<std::string> read_whole_file(const std::string& path);

}  // namespace fosssim
