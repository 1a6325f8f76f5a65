#pragma once
// Grading by output comparison (course-compatible; docs/command-line.md, 'Grading'): replays a
// trajectory file step by step against the scene's own integrator.

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/scene.h"
#include "io/trajectory_file.h"

namespace fosssim {

/// The course's pass criteria: every sum of residuals below `accumulated_limit`, every single
/// position residual (and sync-record residual) below `maximum_limit` and every single velocity
/// residual below `maximum_velocity_limit`, strictly. The defaults are the Theme 1 program's;
/// criteria_for chooses by scene.
struct GradingCriteria {
  double accumulated_limit = 1e-6;
  double maximum_limit = 1e-10;
  double maximum_velocity_limit = 1e-10;
  /// The Theme 4 program's report: a line "Hybrid Collisions Passed: Yes." before the overall
  /// verdict, and a fifth residual-file line "1" (its hybrid-collision flag, always set).
  bool reports_hybrid_collisions = false;
  /// The Theme 4 program grades a file with frames after the scene's last step, ignoring them
  /// (SPEC-elastica section 5, docs/command-line.md 'Grading'); the Theme 1 program's file must
  /// hold exactly steps + 1 frames.
  bool ignores_frames_after_last_step = false;
};

/// The Theme 4 (elastic bodies) program's criteria: as Theme 1's, but a single velocity residual
/// may reach 1e-9 (measured: 1.0e-9 passes, 1.001e-9 fails; SPEC-elastica section 5), and its
/// report has the hybrid-collision line, and frames after the last step are not read.
constexpr GradingCriteria kTheme4Criteria{1e-6, 1e-10, 1e-9, true, true};

/// The criteria of the course program that grades this scene's kind: Theme 4's when the scene
/// declares one of the Theme 4 elastic forces (Scene::grading_theme), else Theme 1's
/// (docs/command-line.md, 'Grading').
GradingCriteria criteria_for(const Scene& scene);

/// Residuals of one step k: the reference step from the file's frame k-1 against its frame k.
struct StepResidual {
  std::int64_t step = 0;
  double sum_position = 0.0;  ///< Σ_p ‖x_ref - x_file‖
  double sum_velocity = 0.0;
  double max_position = 0.0;  ///< max_p ‖x_ref - x_file‖
  double max_velocity = 0.0;
  int max_position_particle = -1;
  int max_velocity_particle = -1;
};

/// Where the file first disagrees with the reference by more than the maximum limit.
struct FirstDivergence {
  std::int64_t step = 0;
  int particle = 0;
  double position_residual = 0.0;
  double velocity_residual = 0.0;
  Vector reference_position, reference_velocity;  ///< the reference step's result (dim values)
  Vector file_position, file_velocity;            ///< the file's frame `step`
  Vector previous_position, previous_velocity;    ///< the file's frame `step - 1`, the start
};

/// The comparison of a step's collisions, polynomials and sync record (docs/collisions.md,
/// 'Grading'), for trajectories whose layout has them.
struct CollisionGrade {
  /// At most this many lines are kept, so that grading's memory does not grow with the number
  /// of steps; the others are counted in lines_dropped.
  static constexpr std::size_t kMaxLines = 10000;
  /// The course's report lines, in the order found: "  Missed collision: Particle 0 - Particle 1
  /// with normal = 0.4 0", "Wrong number of polynomials!", and FOSSSim's own sync-record lines.
  std::vector<std::string> lines;
  std::int64_t lines_dropped = 0;  ///< lines found after the first kMaxLines
  std::int64_t missed = 0;
  std::int64_t superfluous = 0;
  std::int64_t wrong_normal = 0;
  std::int64_t polynomial_failures = 0;  ///< steps whose polynomial log is wrong
  std::int64_t sync_failures = 0;        ///< steps whose sync record differs from FOSSSim's
  double max_sync_residual = 0.0;       ///< max over steps and particles of ‖Δx‖ and ‖Δv‖
  std::int64_t first_failing_step = 0;  ///< 0 when every step passed

  bool passed() const {
    return missed == 0 && superfluous == 0 && wrong_normal == 0 && polynomial_failures == 0 &&
           sync_failures == 0;
  }
};

/// What grading found, in memory independent of the number of steps: the four criteria's
/// values, the last step graded and the first divergence. Whoever needs every step's residuals
/// (the oracle's diagnosis) takes them one by one from a StepGrader (grading/step_grader.h).
struct GradeReport {
  GradingCriteria criteria;
  std::int64_t steps = 0;         ///< the steps to grade: the scene's num_steps()
  std::int64_t steps_graded = 0;  ///< steps compared so far
  /// Whole frames the file holds after the scene's last step, not read (only under criteria
  /// that ignore them; otherwise such a file is refused).
  std::int64_t frames_after_last_step = 0;
  double accumulated_position = 0.0;
  double accumulated_velocity = 0.0;
  double max_position = 0.0;
  double max_velocity = 0.0;
  std::optional<StepResidual> last_step;  ///< the residuals of the last step compared
  std::optional<FirstDivergence> first_divergence;
  /// Set when the reference integrator could not take a step from the file's state; the
  /// comparison stops there and the grade is a failure. The step's residuals are undefined:
  /// they count as NaN, so that every criterion fails with it (the printed report and the
  /// residual file say so too).
  std::optional<std::string> reference_failure;
  /// Set when the trajectory's layout records collisions (collision types simple,
  /// continuous-time and hybrid); it must pass too.
  std::optional<CollisionGrade> collisions;

  bool accumulated_position_passed() const;
  bool accumulated_velocity_passed() const;
  bool max_position_passed() const;
  bool max_velocity_passed() const;
  bool passed() const;
};

/// True when `value` is strictly below `limit`, the course's test for passing; false for NaN.
inline bool below_limit(double value, double limit) { return value < limit; }

/// True when `candidate` should replace `current` as a maximum: a NaN beats every number, so that
/// a NaN residual cannot hide behind a finite one.
inline bool replaces_maximum(double candidate, double current) {
  return std::isnan(candidate) ? !std::isnan(current) : candidate > current;
}

/// One of the course's four pass criteria, evaluated on a report.
struct Criterion {
  const char* name;  ///< "Accumulated Position Residual", as the course prints it
  double value;
  double limit;
  bool passed;
};

/// The report's four criteria in the course's order: accumulated position, accumulated velocity,
/// maximum position, maximum velocity residual.
std::array<Criterion, 4> criteria_of(const GradeReport& report);

/// Called after each graded step with (step, total steps).
using GradingProgress = std::function<void(std::int64_t, std::int64_t)>;

/// Grades `file` against `scene`: for every step k overwrites the state with frame k-1, takes one
/// reference step and compares with frame k, for every particle (fixed ones included), with
/// `criteria` or, when none are given, criteria_for(scene). Throws Error (kBadInput) when the
/// file does not hold exactly num_steps() + 1 frames.
GradeReport grade_trajectory(const Scene& scene, TrajectoryReader& file,
                             const std::optional<GradingCriteria>& criteria = std::nullopt,
                             const GradingProgress& progress = {});

/// Prints the course's report lines: the collision report's lines (if any), four
/// "<criterion>: <value>   Passed." lines, "Collisions Passed: Yes." or "No." for trajectories
/// with collisions, "Hybrid Collisions Passed: Yes." under the Theme 4 criteria, then
/// "Overall success: Passed." or "Failed.".
void print_grade_report(std::ostream& out, const GradeReport& report);

/// Writes residual.txt: one "<1|0>   <value>" line per criterion, in the report's order, and under
/// the Theme 4 criteria a fifth line "1". The file is written under a temporary name and
/// renamed, so it is never left half written.
void write_residual_file(const std::string& path, const GradeReport& report);

/// A human explanation of where and why grading failed, for the terminal; empty when passed.
std::string describe_failure(const GradeReport& report, int dim);

}  // namespace fosssim
