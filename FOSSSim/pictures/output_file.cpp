#include "pictures/output_file.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace fosssim {

std::string partial_name(const std::string& path) { return path + ".partial"; }

void move_into_place(const std::string& temporary, const std::string& path) {
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (!error) return;
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
  throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " + error.message());
}

}  // namespace fosssim
