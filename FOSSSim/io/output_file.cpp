#include "io/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "core/error.h"

namespace fs = std::filesystem;

namespace fosssim {

OutputFile::OutputFile(const std::string& path) : final_path_(path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // follows symbolic links
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    in_place_ = true;
    write_path_ = path;
    return;
  }
  if (fs::is_symlink(fs::symlink_status(path, error))) {
    const fs::path target = fs::weakly_canonical(path, error);
    if (!error) final_path_ = target.string();
  }
  write_path_ = final_path_ + ".partial";
}

void OutputFile::commit() const {
  if (in_place_) return;
  std::error_code error;
  fs::rename(write_path_, final_path_, error);
  if (!error) return;
  discard();
  throw Error(ErrorKind::kCannotWrite,
              "cannot rename " + write_path_ + " to " + final_path_ + ": " + error.message());
}

std::string OutputFile::keep_unfinished(const std::string& suffix) const {
  if (in_place_) return write_path_;
  const std::string kept = final_path_ + suffix;
  std::error_code error;
  fs::rename(write_path_, kept, error);
  return error ? "" : kept;
}

void OutputFile::discard() const {
  if (in_place_) return;
  std::error_code ignored;
  fs::remove(write_path_, ignored);
}

void write_output_file(const std::string& path, const std::string& content) {
  const OutputFile output(path);
  const std::string& name = output.write_path();
  const auto fail = [&](const char* reason) {
    throw Error(ErrorKind::kCannotWrite, "cannot write " + name + ": " + reason);
  };
  const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw Error(ErrorKind::kCannotWrite, "cannot create " + name + ": " + std::strerror(errno));
  }
  const auto fail_open = [&](const char* reason) {
    ::close(fd);
    output.discard();
    fail(reason);
  };
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail_open(std::strerror(errno));
    written += static_cast<std::size_t>(n);
  }
  if (!output.in_place() && ::fsync(fd) != 0) fail_open(std::strerror(errno));
  if (::close(fd) != 0) {
    output.discard();
    fail(std::strerror(errno));
  }
  output.commit();
}

void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& body) {
  std::ostringstream content;
  body(content);
  write_output_file(path, content.str());
}

}  // namespace fosssim
