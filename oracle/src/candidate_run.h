#pragma once
// Running a candidate simulator on one scene the way the course's grading script does,
// "CANDIDATE -s SCENE -d 0 -o FILE", in a folder of its own, and checking that FILE is a
// trajectory of the right size before anyone reads it.

#include <cstdint>
#include <optional>
#include <string>

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

struct CandidateRunOptions {
  std::string candidate;  ///< the executable (a path; see resolve_executable)
  double timeout_seconds = 600.0;
};

/// What one run produced.
struct CandidateRun {
  /// Set when the run or its file cannot be graded: crash, timeout, exit status, no file, short
  /// or oversized file. Unset: `trajectory_path` holds exactly `expected_bytes` bytes.
  std::optional<Verdict> problem;
  std::string reason;           ///< one line, when `problem` is set
  std::string trajectory_path;  ///< "<work folder>/out.bin"
  std::string stderr_tail;      ///< the last lines of the candidate's standard error, printable
  int exit_status = 0;
  double seconds = 0.0;
};

/// The size of a complete trajectory of `model`: num_steps() + 1 frames (the initial state and
/// one frame per step), what run_candidate is told to expect. For layouts with collision
/// records (docs/collisions.md) the size depends on what collided: this is then the smallest
/// possible size (no collisions, no polynomials), and trajectory_size_is_exact is false.
std::int64_t expected_trajectory_bytes(const SceneModel& model);

/// True when every complete trajectory of `model` has exactly expected_trajectory_bytes bytes
/// (layouts without collision records).
bool trajectory_size_is_exact(const SceneModel& model);

/// Runs `options.candidate -s <scene_path> -d 0 -o <work>/out.bin` in `work`, with the timeout,
/// a per-file size limit and a watch on the folder's size (both well above `expected_bytes`, so
/// a runaway writer is stopped early), then checks the file's size against `expected_bytes`:
/// exactly, or (`exact` false: layouts with collision records) as a lower bound, leaving the
/// rest to the reader, which checks the records' structure.
CandidateRun run_candidate(const std::string& scene_path, std::int64_t expected_bytes,
                           const CandidateRunOptions& options, const WorkFolder& work,
                           bool exact = true);

}  // namespace fosssim
