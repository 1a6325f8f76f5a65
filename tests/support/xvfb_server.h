#pragma once
// A private virtual X server for window tests: Xvfb picks a free display itself (-displayfd),
// so tests running in parallel, or other programs' servers, never collide.

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <optional>
#include <string>
#include <vector>

extern char** environ;

namespace fosssim::testing {

class XvfbServer {
 public:
  /// Starts Xvfb and waits until it accepts connections; nothing if it cannot be started.
  static std::optional<XvfbServer> start() {
    int fds[2];
    if (::pipe(fds) != 0) return std::nullopt;
    const std::string fd = std::to_string(fds[1]);
    std::vector<std::string> args = {"Xvfb",       "-displayfd", fd,    "-screen", "0",
                                     "800x600x24", "-nolisten",  "tcp", "-noreset"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", 0x1 /*O_WRONLY*/, 0);
    pid_t pid = -1;
    const int spawned = posix_spawnp(&pid, "Xvfb", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (spawned != 0) {
      ::close(fds[0]);
      return std::nullopt;
    }
    // Xvfb writes the display number once it is ready for clients.
    std::string number;
    pollfd wait_for{fds[0], POLLIN, 0};
    while (::poll(&wait_for, 1, 20000) > 0) {
      char c;
      if (::read(fds[0], &c, 1) != 1 || c == '\n') break;
      number += c;
    }
    ::close(fds[0]);
    XvfbServer server(pid, ":" + number);
    if (number.empty()) return std::nullopt;
    return server;
  }

  XvfbServer(XvfbServer&& other) noexcept : pid_(other.pid_), display_(other.display_) {
    other.pid_ = -1;
  }
  XvfbServer& operator=(XvfbServer&& other) noexcept {
    std::swap(pid_, other.pid_);
    std::swap(display_, other.display_);
    return *this;
  }
  ~XvfbServer() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    int status;
    ::waitpid(pid_, &status, 0);
  }

  /// The DISPLAY value of the server, ":3" say.
  const std::string& display() const { return display_; }

 private:
  XvfbServer(pid_t pid, std::string display) : pid_(pid), display_(std::move(display)) {}
  pid_t pid_;
  std::string display_;
};

}  // namespace fosssim::testing
