#include "io/output_file.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

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
  throw std::runtime_error("cannot rename " + write_path_ + " to " + final_path_ + ": " +
                           error.message());
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

}  // namespace fosssim
