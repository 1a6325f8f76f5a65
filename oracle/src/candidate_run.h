#pragma once
// Running a candidate simulator on one scene the way the course's grading script does,
// "CANDIDATE -s SCENE -d 0 -o FILE", confined (sandbox.h) in a folder of its own with limits on
// time, CPU, memory, file size and processes, and checking that FILE is a trajectory of the
// right size before anyone reads it.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/sanitizers.h"
#include "grading/grader.h"
#include "scene_result.h"

namespace fosssim {

struct SceneModel;

/// A fresh temporary folder ("<parent>/fosssim-oracle-XXXXXX"), removed with everything in it
/// when the object is destroyed, unless keep() was called.
class WorkFolder {
 public:
  /// Creates the folder under `parent` (the system's temporary folder when empty). Throws
  /// Error (kCannotWrite) when it cannot.
  explicit WorkFolder(const std::string& parent);
  ~WorkFolder();
  WorkFolder(const WorkFolder&) = delete;
  WorkFolder& operator=(const WorkFolder&) = delete;

  const std::string& path() const { return path_; }
  void keep() { keep_ = true; }

 private:
  std::string path_;
  bool keep_ = false;
};

/// Address space each process of a candidate may map (RLIMIT_AS), by default: 4 GiB. An
/// oracle built with AddressSanitizer sets no such limit by default, because the sanitizer
/// builds it grades (CI's sanitizer preset) reserve terabytes of address space.
#if FOSSSIM_ADDRESS_SANITIZER
constexpr std::int64_t kDefaultCandidateMemoryBytes = -1;
#else
constexpr std::int64_t kDefaultCandidateMemoryBytes = std::int64_t(4) << 30;
#endif
/// Processes a candidate may have at once, by default.
constexpr int kDefaultCandidateProcesses = 64;

struct CandidateRunOptions {
  std::string candidate;  ///< the executable (a path; see resolve_executable)
  double timeout_seconds = 600.0;
  /// Run the candidate in the sandbox of sandbox.h. False (--no-sandbox): run it directly, with
  /// the same limits, seeing and able to write whatever the oracle's user can.
  bool sandbox = true;
  /// The bwrap executable; empty: found in $PATH when a run needs it.
  std::string bwrap;
  /// More files or folders the sandboxed candidate may read (--allow-read), at the same paths.
  std::vector<std::string> readable;
  /// RLIMIT_AS of every process of the candidate, bytes; negative: none.
  std::int64_t max_memory_bytes = kDefaultCandidateMemoryBytes;
  /// Processes the candidate may have at once (ChildLimits::max_processes); 0: no limit.
  int max_processes = kDefaultCandidateProcesses;
};

/// What one run produced.
struct CandidateRun {
  /// Set when the run or its file cannot be graded: crash, timeout, exit status, no file, short
  /// or oversized file. Unset: `trajectory_path` holds exactly `expected_bytes` bytes.
  std::optional<Verdict> problem;
  std::string reason;           ///< one line, when `problem` is set
  std::string trajectory_path;  ///< "<work folder>/run/out.bin"
  std::string stderr_tail;      ///< the last lines of the candidate's standard error, printable
  int exit_status = 0;
  double seconds = 0.0;
};

/// The size of a complete trajectory of `model`: num_steps() + 1 frames (the initial state and
/// one frame per step), what run_candidate is told to expect. For layouts with collision
/// records (docs/collisions.md) the size depends on what collided: this is then the smallest
/// possible size (no collisions, no polynomials), and trajectory_size_is_exact is false.
std::int64_t expected_trajectory_bytes(const SceneModel& model);

/// How a finished trajectory's size is checked against expected_trajectory_bytes.
enum class TrajectorySize {
  kExact,           ///< exactly: frames without collision records
  kAtLeastFrames,   ///< at least: frames, of which those after the last step are not read
                    ///< (the Theme 4 program's rule, GradingCriteria::ignores_frames_after_last_step)
  kAtLeastRecords,  ///< at least: records with collisions, whose sizes vary (the reader checks
                    ///< their structure)
};

/// True when every complete trajectory of `model` has exactly expected_trajectory_bytes bytes
/// (layouts without collision records).
bool trajectory_size_is_exact(const SceneModel& model);

/// The size rule of `model`'s trajectories as graded under `criteria`.
TrajectorySize trajectory_size_rule(const SceneModel& model, const GradingCriteria& criteria);

/// Runs `options.candidate -s <scene_path> -d 0 -o <work>/run/out.bin` in `<work>/run`, with the
/// timeout, the CPU-time limit (the timeout, rounded up), the memory and process limits, a
/// per-file size limit and a watch on the folder's size (both well above `expected_bytes`, so
/// a runaway writer is stopped early), then checks the file's size against `expected_bytes` by
/// `size` (a lower bound leaves the rest to the reader, which checks the records' structure). Sandboxed, the candidate reads the
/// folders of `scene_files` (the files the scene reads; the scene's folder when empty), its
/// own folder and `options.readable`, and writes only `<work>/run` and its private /tmp.
CandidateRun run_candidate(const std::string& scene_path, std::int64_t expected_bytes,
                           const CandidateRunOptions& options, const WorkFolder& work,
                           TrajectorySize size = TrajectorySize::kExact,
                           const std::vector<std::string>& scene_files = {});

}  // namespace fosssim
