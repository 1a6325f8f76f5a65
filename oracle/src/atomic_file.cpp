#include "atomic_file.h"

#include <filesystem>

#include "io/output_file.h"
#include "io/text_lines.h"

namespace fosssim {

std::optional<std::string> write_file_atomically(const std::string& path,
                                                 const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code error;
    fs::create_directories(parent, error);
    if (error) return "cannot create the folder " + parent.string() + ": " + error.message();
  }
  return write_output_file(path, content);
}

std::optional<std::string> read_whole_file(const std::string& path) {
  auto text = read_text_file(path);
  if (!text) return std::nullopt;
  return std::move(text).value();
}

}  // namespace fosssim
