#include "child_process.h"

#include <fcntl.h>
#include <linux/close_range.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "seconds_since.h"

extern char** environ;

namespace fosssim {

namespace {

std::atomic<bool> g_stop_requested{false};

using Clock = std::chrono::steady_clock;

/// Keeps the last `limit` bytes appended, and counts all of them.
struct Tail {
  std::string bytes;
  std::int64_t total = 0;
  std::size_t limit = 0;

  void append(const char* data, std::size_t size) {
    total += static_cast<std::int64_t>(size);
    bytes.append(data, size);
    if (bytes.size() > 2 * limit + 4096) bytes.erase(0, bytes.size() - limit);
  }
  std::string take() {
    if (bytes.size() > limit) bytes.erase(0, bytes.size() - limit);
    return std::move(bytes);
  }
};

/// Reads what is available on a non-blocking descriptor; closes it (and sets it to -1) at end
/// of file or on an error other than EAGAIN.
void read_available(int& fd, Tail& tail) {
  char buffer[8192];
  while (fd >= 0) {
    const ssize_t got = ::read(fd, buffer, sizeof(buffer));
    if (got > 0) {
      tail.append(buffer, static_cast<std::size_t>(got));
    } else if (got < 0 && errno == EINTR) {
      continue;
    } else if (got < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      return;
    } else {
      ::close(fd);
      fd = -1;
    }
  }
}

/// Waits up to `milliseconds` for output on the open descriptors, or for the child to end
/// (`process_fd`, a pidfd, becomes readable then; -1 when the kernel has none), and reads the
/// output.
void poll_output(int& out_fd, Tail& out, int& err_fd, Tail& err, int process_fd, int milliseconds) {
  pollfd fds[3];
  nfds_t count = 0;
  if (out_fd >= 0) fds[count++] = {out_fd, POLLIN, 0};
  if (err_fd >= 0) fds[count++] = {err_fd, POLLIN, 0};
  if (process_fd >= 0) fds[count++] = {process_fd, POLLIN, 0};
  if (count == 0) {
    // Both pipes are closed and there is no pidfd: the child is about to end; look again soon.
    ::usleep(static_cast<useconds_t>(std::min(milliseconds, 2)) * 1000);
    return;
  }
  if (::poll(fds, count, milliseconds) > 0) {
    read_available(out_fd, out);
    read_available(err_fd, err);
  }
}

/// True once the child has ended; leaves it a zombie (WNOWAIT) so that its process id, and with
/// it the process group id, cannot be reused before we kill the group and reap it.
bool child_has_ended(pid_t pid) {
  siginfo_t info;
  std::memset(&info, 0, sizeof(info));
  if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) != 0) {
    return errno != EINTR;  // ECHILD: nothing left to wait for
  }
  return info.si_pid == pid;
}

/// Everything the child needs, prepared before fork so that the child allocates nothing.
struct ExecPlan {
  std::vector<std::string> args;
  std::vector<char*> argv;
  std::string working_dir;
  std::int64_t max_file_bytes;
  std::int64_t max_cpu_seconds;
  std::int64_t max_address_space_bytes;
};

/// Sets one resource limit (soft and hard); false when the system refuses.
bool set_limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit limit{soft, hard};
  return ::setrlimit(resource, &limit) == 0;
}

/// Runs in the forked child: only async-signal-safe calls until exec. Reports a failure as
/// (step, errno) on `report_fd` and exits.
[[noreturn]] void exec_child(const ExecPlan& plan, int out_fd, int err_fd, int report_fd) {
  auto fail = [report_fd](int step) {
    const int message[2] = {step, errno};
    [[maybe_unused]] ssize_t ignored = ::write(report_fd, message, sizeof(message));
    ::_exit(127);
  };
  ::setpgid(0, 0);
  // Descriptors other threads opened without O_CLOEXEC must not reach the candidate.
  ::close_range(3, ~0U, CLOSE_RANGE_CLOEXEC);
  struct sigaction default_action;
  std::memset(&default_action, 0, sizeof(default_action));
  default_action.sa_handler = SIG_DFL;
  for (int s : {SIGINT, SIGTERM, SIGPIPE, SIGXFSZ, SIGXCPU})
    ::sigaction(s, &default_action, nullptr);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  if (::chdir(plan.working_dir.c_str()) != 0) fail(1);
  const int null_fd = ::open("/dev/null", O_RDONLY);
  if (null_fd < 0 || ::dup2(null_fd, STDIN_FILENO) < 0 || ::dup2(out_fd, STDOUT_FILENO) < 0 ||
      ::dup2(err_fd, STDERR_FILENO) < 0) {
    fail(2);
  }
  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
  if (plan.max_file_bytes >= 0) {
    const auto bytes = static_cast<rlim_t>(plan.max_file_bytes);
    if (!set_limit(RLIMIT_FSIZE, bytes, bytes)) fail(3);
  }
  if (plan.max_cpu_seconds >= 0) {
    const auto seconds = static_cast<rlim_t>(plan.max_cpu_seconds);
    if (!set_limit(RLIMIT_CPU, seconds, seconds + 1)) fail(3);
  }
  if (plan.max_address_space_bytes >= 0) {
    const auto bytes = static_cast<rlim_t>(plan.max_address_space_bytes);
    if (!set_limit(RLIMIT_AS, bytes, bytes)) fail(3);
  }
  ::execve(plan.argv[0], plan.argv.data(), environ);
  fail(0);
  ::_exit(127);
}

const char* start_step_name(int step) {
  switch (step) {
    case 0:
      return "exec";
    case 1:
      return "chdir";
    case 2:
      return "redirect";
    case 3:
      return "setrlimit";
    default:
      return "start";
  }
}

/// Opens a pipe whose ends are closed on exec, so that no other child inherits them.
bool open_pipe(int fds[2]) { return ::pipe2(fds, O_CLOEXEC) == 0; }

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

ChildOutcome cannot_start(const char* step, int error) {
  ChildOutcome outcome;
  outcome.ending = ChildEnding::kCannotStart;
  outcome.start_step = step;
  outcome.start_error = error;
  return outcome;
}

}  // namespace

void stop_all_children() { g_stop_requested.store(true); }
bool children_stopped() { return g_stop_requested.load(); }

ChildOutcome run_child(const std::vector<std::string>& args, const std::string& working_dir,
                       const ChildLimits& limits) {
  ExecPlan plan{args,
                {},
                working_dir,
                limits.max_file_bytes,
                limits.max_cpu_seconds,
                limits.max_address_space_bytes};
  for (std::string& arg : plan.args) plan.argv.push_back(arg.data());
  plan.argv.push_back(nullptr);

  int out_pipe[2], err_pipe[2], report_pipe[2];
  if (!open_pipe(out_pipe)) return cannot_start("pipe", errno);
  if (!open_pipe(err_pipe)) {
    const int error = errno;
    ::close(out_pipe[0]), ::close(out_pipe[1]);
    return cannot_start("pipe", error);
  }
  if (!open_pipe(report_pipe)) {
    const int error = errno;
    for (int fd : {out_pipe[0], out_pipe[1], err_pipe[0], err_pipe[1]}) ::close(fd);
    return cannot_start("pipe", error);
  }

  const Clock::time_point start = Clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) exec_child(plan, out_pipe[1], err_pipe[1], report_pipe[1]);
  const int fork_error = errno;
  for (int fd : {out_pipe[1], err_pipe[1], report_pipe[1]}) ::close(fd);
  int out_fd = out_pipe[0], err_fd = err_pipe[0];
  if (pid < 0) {
    for (int fd : {out_fd, err_fd, report_pipe[0]}) ::close(fd);
    return cannot_start("fork", fork_error);
  }
  ::setpgid(pid, pid);  // also done by the child; whichever runs first wins the race
  const int process_fd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));

  // The report pipe closes on a successful exec, or carries (step, errno) on failure.
  int report[2] = {0, 0};
  ssize_t got = 0;
  do {
    got = ::read(report_pipe[0], report, sizeof(report));
  } while (got < 0 && errno == EINTR);
  ::close(report_pipe[0]);
  if (got == static_cast<ssize_t>(sizeof(report))) {
    ::waitpid(pid, nullptr, 0);
    ::close(out_fd), ::close(err_fd);
    if (process_fd >= 0) ::close(process_fd);
    return cannot_start(start_step_name(report[0]), report[1]);
  }

  ::fcntl(out_fd, F_SETFL, ::fcntl(out_fd, F_GETFL) | O_NONBLOCK);
  ::fcntl(err_fd, F_SETFL, ::fcntl(err_fd, F_GETFL) | O_NONBLOCK);
  Tail out{{}, 0, limits.tail_bytes}, err{{}, 0, limits.tail_bytes};
  ChildOutcome outcome;
  outcome.ending = ChildEnding::kExited;
  Clock::time_point last_watch = start;
  while (!child_has_ended(pid)) {
    if (g_stop_requested.load()) {
      outcome.ending = ChildEnding::kInterrupted;
      break;
    }
    if (seconds_since(start) >= limits.timeout_seconds) {
      outcome.ending = ChildEnding::kTimedOut;
      break;
    }
    if ((limits.watch || limits.max_processes > 0) &&
        Clock::now() - last_watch >= std::chrono::milliseconds(50)) {
      last_watch = Clock::now();
      std::optional<std::string> message = limits.watch ? limits.watch() : std::nullopt;
      if (!message && limits.max_processes > 0) {
        const int processes = count_descendants(pid);
        if (processes > limits.max_processes) {
          message = "the candidate had " + std::to_string(processes) +
                    " processes running at once, more than the limit of " +
                    std::to_string(limits.max_processes) + ", and was stopped";
        }
      }
      if (message) {
        outcome.ending = ChildEnding::kStoppedByWatch;
        outcome.watch_message = std::move(*message);
        break;
      }
    }
    const double left_ms = 1000.0 * (limits.timeout_seconds - seconds_since(start));
    poll_output(out_fd, out, err_fd, err, process_fd,
                static_cast<int>(std::clamp(left_ms, 1.0, 50.0)));
  }
  if (process_fd >= 0) ::close(process_fd);
  // Kill the whole group: the child if it still runs, and whatever it started and left behind.
  ::kill(-pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  outcome.seconds = seconds_since(start);
  if (outcome.ending == ChildEnding::kExited) {
    if (WIFSIGNALED(status)) {
      outcome.ending = ChildEnding::kSignaled;
      outcome.signal = WTERMSIG(status);
    } else {
      outcome.exit_status = WEXITSTATUS(status);
    }
  }
  // Collect what is still buffered in the pipes; a process that escaped the group (a daemon in
  // its own session) could hold them open, so give up after a short while.
  const Clock::time_point drain_start = Clock::now();
  while ((out_fd >= 0 || err_fd >= 0) && seconds_since(drain_start) < 0.5) {
    poll_output(out_fd, out, err_fd, err, -1, 20);
  }
  close_fd(out_fd);
  close_fd(err_fd);
  outcome.stdout_bytes = out.total;
  outcome.stderr_bytes = err.total;
  outcome.stdout_tail = out.take();
  outcome.stderr_tail = err.take();
  return outcome;
}

std::string resolve_executable(const std::string& name) {
  namespace fs = std::filesystem;
  if (name.empty()) return "";
  if (name.find('/') != std::string::npos) {
    std::error_code error;
    const fs::path absolute = fs::absolute(name, error);
    return error ? name : absolute.lexically_normal().string();
  }
  const char* path = std::getenv("PATH");
  std::string directories = path ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= directories.size()) {
    std::size_t end = directories.find(':', begin);
    if (end == std::string::npos) end = directories.size();
    std::string directory = directories.substr(begin, end - begin);
    const std::string candidate = (fs::path(directory.empty() ? "." : directory) / name).string();
    struct stat info;
    if (::stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      std::error_code error;
      const fs::path absolute = fs::absolute(candidate, error);
      return error ? candidate : absolute.lexically_normal().string();
    }
    begin = end + 1;
  }
  return "";
}

std::string why_not_found(const std::string& name) {
  struct stat info;
  const bool here = ::stat(name.c_str(), &info) == 0;
  if (name.find('/') != std::string::npos) return here ? "cannot be run" : "does not exist";
  if (here && S_ISREG(info.st_mode) && ::access(name.c_str(), X_OK) == 0) {
    return "is not on PATH; the current folder has one, so give ./" + name +
           " (a name without a '/' is looked for in the PATH, never in the current folder)";
  }
  return "is not on PATH (give its path, such as ./" + name + ", if it is not installed)";
}

int count_descendants(int pid) {
  namespace fs = std::filesystem;
  // Parent links of every process; /proc/N/stat is "N (command) state ppid ...", and the
  // command may hold spaces and parentheses, so the fields after the last ')' are read.
  std::unordered_map<int, int> parent;
  std::error_code error;
  for (fs::directory_iterator it("/proc", error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(it->path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;  // the process ended meanwhile
    const std::size_t close = line.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream fields(line.substr(close + 1));
    std::string state;
    int ppid = 0;
    if (fields >> state >> ppid) parent[std::atoi(name.c_str())] = ppid;
  }
  int count = 0;
  for (const auto& [process, first_parent] : parent) {
    // Walk up at most as many links as there are processes (a cycle cannot occur, but a
    // snapshot taken while processes come and go is not guaranteed to be consistent).
    int up = first_parent;
    for (std::size_t steps = 0; up > 0 && steps < parent.size(); ++steps) {
      if (up == pid) {
        ++count;
        break;
      }
      const auto next = parent.find(up);
      if (next == parent.end()) break;
      up = next->second;
    }
  }
  return count;
}

std::string describe_signal(int signal) {
  const char* abbreviation = ::sigabbrev_np(signal);
  const char* description = ::sigdescr_np(signal);
  std::string text =
      abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
  if (description) text += std::string(" (") + description + ")";
  return text;
}

}  // namespace fosssim
