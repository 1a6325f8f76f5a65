#pragma once
// What grading one scene found: the verdict, why, and the residuals. Every report (terminal
// table, JUnit XML, Gradescope JSON, shard files) is written from a list of these.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fosssim {

/// The outcome of one scene. Only kPassed passes.
enum class Verdict {
  kPassed,       ///< the trajectory meets the course's criteria
  kFailed,       ///< the trajectory was graded and misses a criterion
  kCrashed,      ///< the candidate was killed by a signal
  kTimedOut,     ///< the candidate ran past the timeout
  kExitStatus,   ///< the candidate exited with a non-zero status
  kNoOutput,     ///< the candidate wrote no trajectory, or an empty one
  kShort,        ///< fewer bytes than steps + 1 frames
  kOversized,    ///< more bytes than steps + 1 frames (or it kept on writing)
  kGarbage,      ///< the right size, but holds NaN or infinite values
  kCannotRun,    ///< the candidate does not exist or cannot be executed
  kSceneError,   ///< the scene file itself cannot be loaded: a problem of the suite, not the
                 ///< candidate
  kInterrupted,  ///< the oracle was stopped (Ctrl-C) while this scene ran
};

/// Upper-case label for the terminal table: "PASS", "FAIL", "CRASH", "TIMEOUT", ...
const char* verdict_label(Verdict verdict);
/// Stable lower-case identifier for files: "passed", "failed", "crashed", "timeout", ...
const char* verdict_id(Verdict verdict);
/// The verdict of an identifier, if it is one.
std::optional<Verdict> verdict_from_id(std::string_view id);

/// The course's four residual figures (docs/command-line.md, 'Grading').
struct Residuals {
  double accumulated_position = 0.0;
  double accumulated_velocity = 0.0;
  double max_position = 0.0;
  double max_velocity = 0.0;
};

/// The first step and particle (or rigid body) whose residual reaches the maximum limit.
struct DivergencePoint {
  std::int64_t step = 0;
  int particle = 0;  ///< the particle's index, or the body's in a Theme 3 scene (rigid_body)
  double position_residual = 0.0;
  double velocity_residual = 0.0;
  bool rigid_body = false;  ///< particle is a rigid body's index (a Theme 3 scene)

  /// What `particle` counts, for reports: "body" or "particle".
  const char* object() const { return rigid_body ? "body" : "particle"; }
};

struct SceneResult {
  std::string name;  ///< SceneEntry::name, "assets/t1m1/springs_single.xml"
  bool extra_credit = false;
  std::string integrator;  ///< canonical name; empty when the scene could not be loaded
  int dim = 0;
  int particles = 0;
  std::int64_t steps = 0;
  double dt = 0.0;
  Verdict verdict = Verdict::kFailed;
  std::string reason;                  ///< one line: why it failed (empty when passed)
  std::string details;                 ///< several lines: the diagnosis (first divergence, states)
  std::string stderr_tail;             ///< the candidate's last lines of standard error, printable
  std::optional<Residuals> residuals;  ///< when the trajectory was graded
  std::optional<DivergencePoint> first_divergence;
  double run_seconds = 0.0;    ///< the candidate's wall time
  double grade_seconds = 0.0;  ///< the oracle's grading time

  bool passed() const { return verdict == Verdict::kPassed; }
  /// The scene's time in the reports: the candidate's run plus the oracle's grading.
  double seconds() const { return run_seconds + grade_seconds; }
  /// The report group: the folder part of the name.
  std::string suite() const;
};

/// The folder part of a scene name ("assets/t1m1" for "assets/t1m1/springs.xml"), or "." for a
/// name without a folder: the group a scene is reported in.
std::string suite_of_scene(const std::string& name);

}  // namespace fosssim
