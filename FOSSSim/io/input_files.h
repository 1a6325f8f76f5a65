#pragma once
// Reading input files safely: regular files only, never more than a limit, and a record of
// every file read so that no output of the run can replace one.

#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/limits.h"
#include "io/scene_error.h"

namespace fosssim {

/// A regular file open for reading, and its size in bytes when it was opened.
struct RegularFile {
  struct Closer {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  std::unique_ptr<std::FILE, Closer> stream;
  std::int64_t size = 0;
};

/// Opens `path` for reading when it is a regular file (a symbolic link is followed). Refuses,
/// with a SceneError naming the file and the problem, a missing or unreadable file, a folder,
/// and a FIFO, socket or device such as /dev/zero: these are recognised before anything is
/// read, and the file is opened without waiting, so a FIFO with no writer cannot block the run.
RegularFile open_regular_file(const std::string& path);

/// The whole content of the regular file at `path`. Throws SceneError as open_regular_file does,
/// and when the file holds more than `max_bytes` bytes (the message names the limit and
/// --max-file-size); reading stops there even if the file grows while it is read.
std::string read_text_file(const std::string& path,
                           std::int64_t max_bytes = Limits{}.max_file_bytes);

/// The files one scene is read from: the scene file, then the mesh files it names, read with
/// read_text_file under `limits` (or served from memory, for fuzzers and tests). Remembers every
/// path read, so that a program can check that none of its outputs is one of them
/// (io/file_identity.h).
class InputFiles {
 public:
  explicit InputFiles(const Limits& limits = {}) : limits_(limits) {}

  /// Serves files from memory instead of the file system: read(path) returns files[path] and
  /// refuses every other path as missing, without touching the disk.
  static InputFiles in_memory(std::map<std::string, std::string> files, const Limits& limits = {});

  /// The content of the file at `path`. Throws SceneError naming it and the problem.
  std::string read(const std::string& path);

  const Limits& limits() const { return limits_; }
  /// Every path read so far, in order.
  const std::vector<std::string>& paths() const { return paths_; }

 private:
  Limits limits_;
  std::optional<std::map<std::string, std::string>> memory_;
  std::vector<std::string> paths_;
};

}  // namespace fosssim
