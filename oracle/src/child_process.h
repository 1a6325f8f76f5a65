#pragma once
// Runs another program (a candidate simulator) as a child process that cannot hang, flood or
// outlive the oracle: its own process group, a deadline, a file-size limit, no core dumps, and
// only the tail of its output kept.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fosssim {

/// How a child process ended.
enum class ChildEnding {
  kExited,          ///< returned from main or called exit(); see exit_status
  kSignaled,        ///< killed by a signal it did not handle (a crash); see signal
  kTimedOut,        ///< still running at the deadline; its process group was killed
  kStoppedByWatch,  ///< the watch callback asked to stop it; its process group was killed
  kInterrupted,     ///< stop_all_children() was called; its process group was killed
  kCannotStart,     ///< fork, chdir or exec failed; see start_error
};

struct ChildLimits {
  double timeout_seconds = 600.0;
  /// RLIMIT_FSIZE for the child and everything it starts: a write beyond this many bytes in any
  /// one file fails with SIGXFSZ. Negative: no limit.
  std::int64_t max_file_bytes = -1;
  /// RLIMIT_CPU: seconds of CPU time each process of the child may use before SIGXCPU (the
  /// soft limit) and SIGKILL (one second later). Negative: no limit.
  std::int64_t max_cpu_seconds = -1;
  /// RLIMIT_AS: bytes of address space each process of the child may map; an allocation beyond
  /// it fails. Negative: no limit.
  std::int64_t max_address_space_bytes = -1;
  /// Processes the child and its descendants may have at once, counted from /proc about every
  /// 50 ms; more stops the child (kStoppedByWatch). 0: no limit. (RLIMIT_NPROC counts every
  /// process of the user on the machine and does not bind root, so it cannot be used.)
  int max_processes = 0;
  /// Bytes of standard output and standard error to keep (the last ones).
  std::size_t tail_bytes = 4096;
  /// Called about every 50 ms while the child runs; returning a message stops the child
  /// (kStoppedByWatch, message in ChildOutcome::watch_message).
  std::function<std::optional<std::string>()> watch;
};

struct ChildOutcome {
  ChildEnding ending = ChildEnding::kCannotStart;
  int exit_status = 0;        ///< kExited
  int signal = 0;             ///< kSignaled
  int start_error = 0;        ///< kCannotStart: errno of the step that failed
  std::string start_step;     ///< kCannotStart: "exec", "chdir", "fork", "pipe"
  std::string watch_message;  ///< kStoppedByWatch
  std::string stdout_tail;    ///< raw bytes, the last ChildLimits::tail_bytes
  std::string stderr_tail;
  std::int64_t stdout_bytes = 0;  ///< all bytes written, kept or not
  std::int64_t stderr_bytes = 0;
  double seconds = 0.0;  ///< wall time from start to end
};

/// Runs argv[0] (a path; no PATH search, no shell) with arguments argv[1..] in `working_dir`,
/// standard input from /dev/null, standard output and error captured. The child gets its own
/// process group, which is killed with SIGKILL when it times out, is stopped, or has exited
/// (so that nothing it started lingers). Safe to call from several threads at once.
ChildOutcome run_child(const std::vector<std::string>& argv, const std::string& working_dir,
                       const ChildLimits& limits);

/// Makes every running and future run_child() stop its child (kInterrupted). Async-signal-safe,
/// for a SIGINT handler.
void stop_all_children();

/// True once stop_all_children() was called.
bool children_stopped();

/// The path that exec would run for `name`: `name` itself (made absolute) when it holds a '/',
/// otherwise the first executable file called `name` in $PATH; empty when none is found.
std::string resolve_executable(const std::string& name);

/// Why resolve_executable(name) found nothing, as the end of "the candidate NAME ...": "is not
/// on PATH; the current folder has one, so give ./NAME (the PATH is searched for a name without
/// a '/', never the current folder)" when `name` has no '/' and the current folder holds an
/// executable of that name; otherwise "does not exist" or "is not on PATH".
std::string why_not_found(const std::string& name);

/// How many processes descend from `pid` (children, their children, ...), not counting `pid`
/// itself, from the parent links in /proc; 0 when /proc cannot be read.
int count_descendants(int pid);

/// "SIGSEGV (Segmentation fault)" for a signal number.
std::string describe_signal(int signal);

}  // namespace fosssim
