#pragma once
// Report files appear whole or not at all.

#include <string>

namespace fosssim {

/// Creates missing parent folders, then writes `content` with write_output_file
/// (io/output_file.h), so that a reader never sees half a report. Throws Error (kCannotWrite)
/// naming the file and the system's reason.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace fosssim
