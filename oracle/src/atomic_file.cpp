#include "atomic_file.h"

#include <filesystem>

#include "io/output_file.h"
#include "io/text_lines.h"

namespace fosssim {

void write_file_atomically(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code error;
    fs::create_directories(parent, error);
    if (error) {
      throw Error(ErrorKind::kCannotWrite,
                  "cannot create the folder " + parent.string() + ": " + error.message());
    }
  }
  write_output_file(path, content);
}

}  // namespace fosssim
