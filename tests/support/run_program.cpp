#include "support/run_program.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>

namespace fosssim::testing {

namespace {

/// An anonymous temporary file (no name in any folder), closed when it goes.
using CaptureFile = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

CaptureFile capture_file() {
  CaptureFile file(std::tmpfile(), &std::fclose);
  if (!file) throw std::runtime_error("tmpfile failed");
  return file;
}

std::string contents(std::FILE* file) {
  std::string text;
  std::rewind(file);
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) text.append(buffer, n);
  return text;
}

}  // namespace

ProgramResult run_program(const std::vector<std::string>& argv, const std::string& directory) {
  if (argv.empty()) throw std::invalid_argument("run_program: no program");
  const CaptureFile out = capture_file(), err = capture_file();
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    if (::chdir(directory.c_str()) != 0) ::_exit(127);
    ::dup2(::fileno(out.get()), STDOUT_FILENO);
    ::dup2(::fileno(err.get()), STDERR_FILENO);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ProgramResult result;
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = contents(out.get());
  result.err = contents(err.get());
  return result;
}

ProgramResult run_command(const ScratchFolder& folder, const std::string& command_line) {
  return run_program({"/bin/sh", "-c", command_line}, folder.path().string());
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

bool on_path(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

std::string probe_movie(const ScratchFolder& folder, const std::string& movie) {
  return run_command(folder,
                     "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                     "stream=nb_read_frames,width,height,r_frame_rate -of "
                     "default=nw=1:nk=1 " +
                         quoted(movie) + " | tr '\\n' ,")
      .out;
}

}  // namespace fosssim::testing
