#pragma once
// The plot of a trajectory's per-step residuals over time, on a logarithmic axis, with the
// course's maximum limit and the first divergence marked: a LinePlot (pictures/line_plot.h),
// which write_line_plot() writes as SVG or PNG.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grading/grader.h"
#include "pictures/line_plot.h"

namespace fosssim {

/// The largest position and velocity residuals of a run's steps, reduced as the steps come into
/// at most `max_points` columns of consecutive steps (as even as the count allows), each keeping
/// its largest residuals, a NaN beating every number: a plot of any run takes the same memory.
class ResidualColumns {
 public:
  struct Column {
    std::int64_t last_step = 0;  ///< the last step in the column, for the time axis
    double position = 0.0;       ///< the largest max_position of its steps
    double velocity = 0.0;       ///< the largest max_velocity of its steps
  };

  /// For a run of `steps` steps; fewer may come when grading stops early.
  explicit ResidualColumns(std::int64_t steps, int max_points = 1500);

  /// Takes the next step's residuals.
  void add(const StepResidual& residual);

  /// The columns reached so far, in order.
  const std::vector<Column>& columns() const { return columns_; }

 private:
  std::int64_t base_size_ = 0;  ///< steps per column; the first `larger_` hold one more
  std::int64_t larger_ = 0;
  std::int64_t max_columns_ = 0;
  std::int64_t in_last_ = 0;  ///< steps in the last column so far
  std::vector<Column> columns_;
};

struct ResidualPlotOptions {
  std::string title;
  double dt = 0.01;                         ///< seconds per step, for the time axis
  double limit = 1e-10;                     ///< the maximum limit, drawn as a dashed line
  /// The maximum velocity limit when it differs from `limit` (Theme 4: 1e-9), drawn as a
  /// second dashed line; none when velocities are held to `limit` too.
  std::optional<double> velocity_limit;
  std::optional<std::int64_t> marked_step;  ///< the first divergence, drawn as a vertical line
  int max_points = 1500;                    ///< longer runs are reduced to this many columns, each
                                            ///< keeping its largest residual (ResidualColumns)
};

/// The plot of the max over particles of the position and of the velocity residual at every
/// step against simulated time, y on a log10 axis spanning whole decades from below the smallest
/// positive residual (or the limit) to above the largest finite one, at least two. Exact zeros
/// get a bottom line of their own, labelled 0, one decade below the smallest residual;
/// non-finite residuals sit on the top edge. The note says when either occurs.
LinePlot residual_plot(const ResidualColumns& columns, const ResidualPlotOptions& options);

/// The same for every step's residuals at hand, reduced to options.max_points columns.
LinePlot residual_plot(const std::vector<StepResidual>& per_step,
                       const ResidualPlotOptions& options);

}  // namespace fosssim
