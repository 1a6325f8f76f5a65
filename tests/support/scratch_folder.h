#pragma once
// A fresh folder for the files one test writes and the programs it runs, and reading files back.

#include <filesystem>
#include <string>

namespace fosssim::testing {

/// An empty folder of its own for the running test, under the system's temporary directory,
/// named after the test and the process (so tests running in parallel never share one), and
/// removed with everything in it when the test ends. Create it inside a test or a fixture.
class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// The path of `name` (a file or folder, possibly in subfolders) inside the folder.
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

  /// Writes `bytes` to `name`, creating its subfolders; returns its path.
  std::string write(const std::string& name, const std::string& bytes) const;
  /// The bytes of `name`; empty if it cannot be read.
  std::string read(const std::string& name) const;
  bool exists(const std::string& name) const { return std::filesystem::exists(path_ / name); }

 private:
  std::filesystem::path path_;
};

/// The bytes of the file at `path`; empty if it cannot be read.
std::string read_file(const std::filesystem::path& path);

}  // namespace fosssim::testing
