#pragma once
// Every step's residuals of one grading, taken as they come and kept in memory independent of
// the number of steps: what the diagnosis of a failure reports about them.

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "grading/grader.h"
#include "residual_plot.h"

namespace fosssim {

/// Collects the residuals of each graded step (StepGrader's report().last_step): the steps that
/// fail a maximum limit (position residual at or above criteria.maximum_limit, or velocity
/// residual at or above criteria.maximum_velocity_limit), the largest single residual, the residual plot's columns and, when
/// asked for, the table of every step, which goes to an anonymous temporary file as it grows.
class ResidualHistory {
 public:
  /// For a grading of `steps` steps of `dt` seconds against the maximum limits of `criteria`
  /// (the scene's, criteria_for); `keep_table` keeps the table of every step for write_table().
  ResidualHistory(std::int64_t steps, double dt, const GradingCriteria& criteria,
                  bool keep_table);

  /// Takes the next step's residuals.
  void add(const StepResidual& residual);

  std::int64_t steps_over_limit() const { return over_; }
  std::int64_t first_step_over_limit() const { return first_over_; }  ///< 0 when none
  std::int64_t last_step_over_limit() const { return last_over_; }    ///< 0 when none
  /// The largest single position or velocity residual (NaN beats every number) and its step
  /// (0 when no step was added).
  double worst_residual() const { return worst_; }
  std::int64_t worst_step() const { return worst_step_; }
  const ResidualColumns& columns() const { return columns_; }

  /// Writes the table of every step added, tab-separated with a header: step, time, max
  /// position residual and its particle, max velocity residual and its particle, sums over
  /// particles; written whole or not at all (io/output_file.h). Throws Error (kCannotWrite);
  /// also when the history was made without keep_table.
  void write_table(const std::string& path) const;

 private:
  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };

  double dt_;
  double position_limit_;
  double velocity_limit_;
  std::int64_t over_ = 0, first_over_ = 0, last_over_ = 0, worst_step_ = 0;
  double worst_ = -1.0;
  ResidualColumns columns_;
  std::unique_ptr<std::FILE, FileCloser> table_;  ///< the rows so far, or null
  bool table_failed_ = false;                     ///< a row could not be written
};

}  // namespace fosssim
