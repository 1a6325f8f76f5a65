#include "candidate_run.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "child_process.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/scene_model.h"
#include "core/text.h"
#include "io/rigid_trajectory.h"
#include "io/trajectory_file.h"
#include "printable_text.h"
#include "sandbox.h"

namespace fosssim {

namespace fs = std::filesystem;

namespace {

/// Bytes a run may write into one file or into its folder before it is stopped: twice the
/// expected trajectory (a candidate may keep a temporary copy) and at least 64 MiB.
std::int64_t write_limit(std::int64_t expected_bytes) {
  return std::max<std::int64_t>(2 * expected_bytes, std::int64_t(64) << 20);
}

/// Total size of the regular files under `folder`.
std::int64_t folder_bytes(const std::string& folder) {
  std::int64_t total = 0;
  std::error_code error;
  for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end;
       it.increment(error)) {
    std::error_code size_error;
    if (it->is_regular_file(size_error)) {
      const auto size = it->file_size(size_error);
      if (!size_error) total += static_cast<std::int64_t>(size);
    }
  }
  return total;
}

std::string cannot_start_reason(const ChildOutcome& outcome, const std::string& candidate) {
  if (outcome.start_step == "exec") {
    switch (outcome.start_error) {
      case ENOENT:
        return "the candidate " + candidate + " " + why_not_found(candidate);
      case EACCES:
        return "the candidate " + candidate + " is not executable (permission denied)";
      case ENOEXEC:
        return "the candidate " + candidate +
               " is not a program this system can run (a script needs a #! line)";
      default:
        break;
    }
  }
  return "cannot start the candidate " + candidate + " (" + outcome.start_step +
         " failed: " + std::strerror(outcome.start_error) + ")";
}

/// The verdict for a run that did not end with exit status 0, or nothing.
std::optional<Verdict> classify_ending(const ChildOutcome& outcome,
                                       const CandidateRunOptions& options, std::int64_t limit,
                                       std::string& reason) {
  switch (outcome.ending) {
    case ChildEnding::kCannotStart:
      reason = cannot_start_reason(outcome, options.candidate);
      return Verdict::kCannotRun;
    case ChildEnding::kInterrupted:
      reason = "the oracle was interrupted while the candidate ran";
      return Verdict::kInterrupted;
    case ChildEnding::kTimedOut:
      reason = "the candidate did not finish within the timeout of " +
               to_text(options.timeout_seconds) + " s and was killed";
      return Verdict::kTimedOut;
    case ChildEnding::kStoppedByWatch:
      reason = outcome.watch_message;
      return Verdict::kOversized;
    case ChildEnding::kSignaled:
      if (outcome.signal == SIGXFSZ) {
        reason = "the candidate tried to write a file larger than " + std::to_string(limit) +
                 " bytes and was stopped (SIGXFSZ)";
        return Verdict::kOversized;
      }
      if (outcome.signal == SIGXCPU) {
        reason = "the candidate used more CPU time than its limit of about " +
                 to_text(options.timeout_seconds) + " s and was stopped (SIGXCPU)";
        return Verdict::kTimedOut;
      }
      reason = "the candidate crashed: killed by " + describe_signal(outcome.signal);
      return Verdict::kCrashed;
    case ChildEnding::kExited:
      if (outcome.exit_status != 0) {
        reason = "the candidate exited with status " + std::to_string(outcome.exit_status);
        return Verdict::kExitStatus;
      }
      return std::nullopt;
  }
  return std::nullopt;
}

/// The verdict for a trajectory file of the wrong size, or nothing when it has the right size.
std::optional<Verdict> classify_file(const std::string& path, std::int64_t expected_bytes,
                                     TrajectorySize size, std::string& reason) {
  const bool exact = size == TrajectorySize::kExact;
  std::error_code error;
  if (!fs::exists(path, error)) {
    reason = "the candidate exited with status 0 but wrote no trajectory file";
    if (fs::exists(path + ".incomplete", error) || fs::exists(path + ".partial", error)) {
      reason +=
          " (only an unfinished " + fs::path(path).filename().string() + ".incomplete or .partial)";
    }
    return Verdict::kNoOutput;
  }
  const auto bytes = static_cast<std::int64_t>(fs::file_size(path, error));
  if (error) {
    reason = "cannot read the trajectory file: " + error.message();
    return Verdict::kNoOutput;
  }
  if (bytes == 0) {
    reason = "the candidate wrote an empty trajectory file";
    return Verdict::kNoOutput;
  }
  if (bytes < expected_bytes) {
    reason = "short trajectory: " + std::to_string(bytes) + " bytes, but the scene needs " +
             (exact ? "" : "at least ") + std::to_string(expected_bytes) +
             (size == TrajectorySize::kAtLeastRecords ? " (steps + 1 records without collisions)"
                                                      : " (steps + 1 frames)");
    return Verdict::kShort;
  }
  if (exact && bytes > expected_bytes) {
    reason = "oversized trajectory: " + std::to_string(bytes) + " bytes, but the scene needs " +
             std::to_string(expected_bytes) + " (steps + 1 frames); not read";
    return Verdict::kOversized;
  }
  return std::nullopt;
}

/// Why `candidate` cannot be started, checked before it is run in the sandbox (where bwrap would
/// report every such problem as its own failure); nothing when it looks like a program.
std::optional<std::string> candidate_problem(const std::string& candidate) {
  struct stat info;
  if (::stat(candidate.c_str(), &info) != 0) {
    return errno == ENOENT
               ? "the candidate " + candidate + " " + why_not_found(candidate)
               : "cannot start the candidate " + candidate + " (" + std::strerror(errno) + ")";
  }
  if (!S_ISREG(info.st_mode)) return "the candidate " + candidate + " is not a file";
  if (::access(candidate.c_str(), X_OK) != 0) {
    return "the candidate " + candidate + " is not executable (permission denied)";
  }
  char magic[4] = {0, 0, 0, 0};
  std::ifstream(candidate, std::ios::binary).read(magic, sizeof(magic));
  if (std::string(magic, 2) != "#!" && std::string(magic, 4) !=
                                           "\x7f"
                                           "ELF") {
    return "the candidate " + candidate +
           " is not a program this system can run (a script needs a #! line)";
  }
  return std::nullopt;
}

/// The folder holding `path`, or the file itself when that folder is the root (binding "/"
/// would show the whole machine).
std::string folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).lexically_normal().parent_path();
  return parent.empty() || parent == parent.root_path() ? path : parent.string();
}

/// What the sandboxed candidate may read: its own folder (also under its real name when it is
/// a symbolic link), the folders of the scene's files, and the extra paths; each once.
std::vector<std::string> readable_paths(const std::string& scene_path,
                                        const std::vector<std::string>& scene_files,
                                        const CandidateRunOptions& options) {
  std::vector<std::string> paths;
  const auto add = [&paths](const std::string& path) {
    std::error_code error;
    const std::string absolute = fs::absolute(path, error).lexically_normal().string();
    if (!error && std::find(paths.begin(), paths.end(), absolute) == paths.end()) {
      paths.push_back(absolute);
    }
  };
  add(folder_of(options.candidate));
  std::error_code error;
  const fs::path real = fs::canonical(options.candidate, error);
  if (!error) add(folder_of(real.string()));
  if (scene_files.empty()) add(folder_of(scene_path));
  for (const std::string& file : scene_files) add(folder_of(file));
  for (const std::string& path : options.readable) add(path);
  return paths;
}

/// A program killed by a signal inside the sandbox shows as bwrap's exit status 128 + signal;
/// reported as the crash it is.
void undo_sandbox_status(ChildOutcome& outcome) {
  if (outcome.ending == ChildEnding::kExited && outcome.exit_status > kSandboxSignalBase &&
      outcome.exit_status < kSandboxSignalBase + 65) {
    outcome.ending = ChildEnding::kSignaled;
    outcome.signal = outcome.exit_status - kSandboxSignalBase;
    outcome.exit_status = 0;
  }
}

}  // namespace

WorkFolder::WorkFolder(const std::string& parent) {
  std::string base = parent;
  if (base.empty()) {
    std::error_code error;
    base = fs::temp_directory_path(error).string();
    if (error) base = "/tmp";
  }
  std::string pattern = base + "/fosssim-oracle-XXXXXX";
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw Error(ErrorKind::kCannotWrite,
                "cannot create a temporary folder in " + base + ": " + std::strerror(errno));
  }
  path_ = pattern;
}

WorkFolder::~WorkFolder() {
  if (keep_) return;
  std::error_code error;
  fs::remove_all(path_, error);
}

CandidateRun run_candidate(const std::string& scene_path, std::int64_t expected_bytes,
                           const CandidateRunOptions& options, const WorkFolder& work,
                           TrajectorySize size, const std::vector<std::string>& scene_files) {
  CandidateRun run;
  const std::string run_folder = work.path() + "/run";
  run.trajectory_path = run_folder + "/out.bin";
  std::error_code made;
  fs::create_directory(run_folder, made);
  if (made) {
    throw Error(ErrorKind::kCannotWrite, "cannot create " + run_folder + ": " + made.message());
  }
  const std::int64_t limit = write_limit(expected_bytes);
  ChildLimits limits;
  limits.timeout_seconds = options.timeout_seconds;
  limits.max_file_bytes = limit;
  // The CPU time of the deadline, rounded up, and a second more: a busy candidate meets the
  // deadline first; one that forks workers is still bounded per process.
  limits.max_cpu_seconds =
      static_cast<std::int64_t>(std::ceil(std::clamp(options.timeout_seconds, 0.0, 1e9))) + 1;
  limits.max_address_space_bytes = options.max_memory_bytes;
  limits.max_processes = options.max_processes;
  limits.watch = [&work, limit]() -> std::optional<std::string> {
    const std::int64_t bytes = folder_bytes(work.path());
    if (bytes <= limit) return std::nullopt;
    return "the candidate wrote " + std::to_string(bytes) + " bytes into its folder, more than " +
           "the limit of " + std::to_string(limit) + ", and was stopped";
  };
  std::vector<std::string> command = {options.candidate,  "-s", scene_path, "-d", "0", "-o",
                                      run.trajectory_path};
  if (options.sandbox) {
    if (auto problem = candidate_problem(options.candidate)) {
      run.problem = Verdict::kCannotRun;
      run.reason = *problem;
      return run;
    }
    SandboxLayout layout;
    layout.bwrap = options.bwrap.empty() ? resolve_executable("bwrap") : options.bwrap;
    if (layout.bwrap.empty()) {
      throw Error(ErrorKind::kUnavailable, "bubblewrap (bwrap) is not installed");
    }
    layout.read_only = readable_paths(scene_path, scene_files, options);
    layout.writable = run_folder;
    layout.scratch_bytes = limit;
    command = sandboxed_command(layout, command);
  }
  ChildOutcome outcome = run_child(command, run_folder, limits);
  if (options.sandbox) undo_sandbox_status(outcome);
  run.seconds = outcome.seconds;
  run.exit_status = outcome.exit_status;
  run.stderr_tail = last_lines(printable_text(outcome.stderr_tail), 20);
  run.problem = classify_ending(outcome, options, limit, run.reason);
  if (!run.problem) {
    run.problem = classify_file(run.trajectory_path, expected_bytes, size, run.reason);
  } else if (*run.problem == Verdict::kExitStatus || *run.problem == Verdict::kCrashed) {
    // A writer killed by its file-size limit inside a script shows as the script's exit status
    // or crash; the oversized file is the better reason.
    std::string file_reason;
    if (classify_file(run.trajectory_path, expected_bytes, size, file_reason) ==
        Verdict::kOversized) {
      run.problem = Verdict::kOversized;
      run.reason = file_reason + " (and " + run.reason.substr(std::string("the ").size()) + ")";
    }
  }
  return run;
}

std::int64_t expected_trajectory_bytes(const SceneModel& model) {
  if (model.rigid_bodies) return rigid_trajectory_bytes(model.num_particles(), model.num_steps());
  const std::int64_t frames = model.num_steps() + 1;
  const std::int64_t frame = trajectory_frame_bytes(model.num_dofs());
  switch (trajectory_layout(model)) {
    case TrajectoryLayout::kFrames:
      break;
    case TrajectoryLayout::kCollisions:
      return saturating_product({frames, frame + 4});
    case TrajectoryLayout::kCollisionsAndPolynomials:  // sync and end record per step
      return saturating_product({saturating_product({2, frames}) - 1, frame + 8});
  }
  return saturating_product({frames, frame});
}

bool trajectory_size_is_exact(const SceneModel& model) {
  return trajectory_layout(model) == TrajectoryLayout::kFrames;
}

TrajectorySize trajectory_size_rule(const SceneModel& model, const GradingCriteria& criteria) {
  if (!trajectory_size_is_exact(model)) return TrajectorySize::kAtLeastRecords;
  return criteria.ignores_frames_after_last_step ? TrajectorySize::kAtLeastFrames
                                                 : TrajectorySize::kExact;
}

}  // namespace fosssim
