#include "io/output_file.h"

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

void stream_output_file(const std::string& path, const std::function<void(std::FILE*)>& body) {
  const OutputFile output(path);
  const std::string& name = output.write_path();
  std::FILE* file = std::fopen(name.c_str(), "wbe");
  if (file == nullptr) {
    throw Error(ErrorKind::kCannotWrite, "cannot create " + name + ": " + std::strerror(errno));
  }
  const auto fail = [&](int error) {
    output.discard();
    throw Error(ErrorKind::kCannotWrite, "cannot write " + name + ": " + std::strerror(error));
  };
  try {
    body(file);
  } catch (...) {
    std::fclose(file);
    output.discard();
    throw;
  }
  if (std::fflush(file) != 0 || std::ferror(file) ||
      (!output.in_place() && ::fsync(::fileno(file)) != 0)) {
    const int error = errno != 0 ? errno : EIO;
    std::fclose(file);
    fail(error);
  }
  if (std::fclose(file) != 0) fail(errno);
  output.commit();
}

void write_output_file(const std::string& path, const std::string& content) {
  stream_output_file(
      path, [&content](std::FILE* file) { std::fwrite(content.data(), 1, content.size(), file); });
}

void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& body) {
  std::ostringstream content;
  body(content);
  write_output_file(path, content.str());
}

}  // namespace fosssim
