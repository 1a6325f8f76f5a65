#pragma once
// Test helpers: a scratch folder per test, and running the FOSSSim program.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fosssim::testing {

/// A fresh empty folder named after the running test, removed at the end of the test.
class ScratchFolder {
 public:
  ScratchFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("fosssim_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

  /// Writes `text` into the file `name` of the folder; returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name) << text;
    return (path_ / name).string();
  }

 private:
  std::filesystem::path path_;
};

/// What a finished program printed and returned.
struct ProgramResult {
  int status = -1;
  std::string out, err;
};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs a shell command line in `folder`, capturing standard output and error.
inline ProgramResult run_command(const ScratchFolder& folder, const std::string& command) {
  const std::string out = folder / "stdout.txt", err = folder / "stderr.txt";
  const std::string line =
      "cd '" + folder.path().string() + "' && (" + command + ") >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(line.c_str());
  ProgramResult result;
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  return result;
}

/// `text` in single quotes, for a shell command line.
inline std::string quoted(const std::string& text) {
  std::string result(1, '\'');
  result += text;
  result += '\'';
  return result;
}

#ifdef FOSSSIM_EXECUTABLE
/// The FOSSSim program built with these tests.
inline std::string fosssim_program() { return FOSSSIM_EXECUTABLE; }
#endif

/// True when `name` is an executable on PATH.
inline bool on_path(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

/// "width,height,rate,frames," of the first video stream of `movie` (a name in `folder`), as
/// ffprobe reads them; needs ffprobe on PATH.
inline std::string probe_movie(const ScratchFolder& folder, const std::string& movie) {
  return run_command(folder,
                     "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                     "stream=nb_read_frames,width,height,r_frame_rate -of "
                     "default=nw=1:nk=1 '" +
                         movie + "' | tr '\\n' ,")
      .out;
}

}  // namespace fosssim::testing
