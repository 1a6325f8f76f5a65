#include "io/file_identity.h"

#include <sys/stat.h>

namespace fosssim {

std::optional<FileIdentity> file_identity(const std::string& path) {
  struct stat status {};
  if (path.empty() || ::stat(path.c_str(), &status) != 0) return std::nullopt;
  return FileIdentity{status.st_dev, status.st_ino};
}

}  // namespace fosssim
