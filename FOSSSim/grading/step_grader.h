#pragma once
// Grading one step at a time (docs/command-line.md, 'Grading'), for the batch grader and the
// window's grading mode.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/scene.h"
#include "core/step/cancellation.h"
#include "core/step/step_pipeline.h"
#include "grading/grader.h"
#include "io/trajectory_file.h"

namespace fosssim {

/// Replays a trajectory file against a scene's own step, one step per call: for step k it
/// restarts from the file's frame k-1, takes one reference step through the scene's step
/// pipeline (core/step/step_pipeline.h: the integrator, then the stages a run has, such as the
/// scene tag's hook) and compares with the file's frame k, for every particle, fixed ones
/// included. Non-finite reference states are compared, not rejected.
/// Trajectories whose layout records collisions (docs/collisions.md) are also compared step by
/// step on their collisions (as sets, normals to 1e-9), their polynomial logs (up to a positive
/// factor) and their sync records, against FOSSSim's own sync state (FOSSSim's addition: the
/// course's grader adopts the file's sync record instead).
/// The report accumulates over the steps graded so far; after each step, report().last_step
/// holds that step's residuals. Memory does not grow with the number of steps.
class StepGrader {
 public:
  /// Starts grading. `scene` and `file` must outlive the grader. Throws Error (kBadInput) when
  /// the file does not hold exactly num_steps() + 1 frames (the message does not name the file),
  /// or, under criteria that ignore frames after the last step (Theme 4's), fewer; the report
  /// then counts the frames left unread (GradeReport::frames_after_last_step).
  /// Without `criteria`, grades with those of the scene's course program (criteria_for).
  /// `cancellation` lets the caller end a reference step in progress: grade_next_step() then
  /// throws StepCancelled (core/step/cancellation.h).
  static StepGrader open(const Scene& scene, TrajectoryReader& file,
                         const std::optional<GradingCriteria>& criteria = std::nullopt,
                         Cancellation cancellation = {});

  /// Grades the next step. Returns false, grading nothing, once every step is graded or the
  /// reference integrator has failed (report().reference_failure says why).
  bool grade_next_step();

  /// True when there is nothing left to grade.
  bool finished() const;
  /// Number of steps graded so far.
  std::int64_t steps_graded() const { return report_.steps_graded; }

  /// The report over the steps graded so far.
  const GradeReport& report() const { return report_; }
  /// The file's frame of the last graded step (frame 0 before any step): what the file says.
  const State& file_state() const { return file_state_; }
  /// ‖x_ref - x_file‖ per particle at the last graded step (empty before any step).
  const std::vector<double>& position_residuals() const { return position_residuals_; }
  /// ‖v_ref - v_file‖ per particle at the last graded step (empty before any step).
  const std::vector<double>& velocity_residuals() const { return velocity_residuals_; }

 private:
  StepGrader(const Scene& scene, TrajectoryReader& file, const GradingCriteria& criteria,
             Cancellation cancellation);
  void compare(const State& reference, const Vector& previous_q, const Vector& previous_v);
  /// Adds one step's residuals to the report's criteria.
  void accumulate(const StepResidual& residual);
  void compare_records(std::int64_t step);

  const Scene* scene_;
  TrajectoryReader* file_;
  StepPipeline pipeline_;
  StepRecord record_;             // what the reference step reported
  TrajectoryRecord sync_record_;  // the file's sync record of the step being graded
  GradeReport report_;
  State file_state_;
  std::vector<double> position_residuals_, velocity_residuals_;
};

}  // namespace fosssim
