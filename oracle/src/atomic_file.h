#pragma once
// Report files appear whole or not at all.

#include <optional>
#include <string>

namespace fosssim {

/// Creates missing parent folders, then writes `content` with write_output_file
/// (io/output_file.h), so that a reader never sees half a report. Returns an error message
/// naming the file and the system's reason, or nothing on success.
std::optional<std::string> write_file_atomically(const std::string& path,
                                                 const std::string& content);

/// read_text_file (io/text_lines.h) without its message: nothing when it cannot be read.
std::optional<std::string> read_whole_file(const std::string& path);

}  // namespace fosssim
