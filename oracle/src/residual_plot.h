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

struct ResidualPlotOptions {
  std::string title;
  double dt = 0.01;                         ///< seconds per step, for the time axis
  double limit = 1e-10;                     ///< the maximum limit, drawn as a dashed line
  std::optional<std::int64_t> marked_step;  ///< the first divergence, drawn as a vertical line
  int max_points = 1500;                    ///< longer runs are reduced to this many columns, each
                                            ///< keeping its largest residual
};

/// The plot of the max over particles of the position and of the velocity residual at every
/// step against simulated time, y on a log10 axis spanning whole decades from below the smallest
/// positive residual (or the limit) to above the largest finite one, at least two. Exact zeros
/// get a bottom line of their own, labelled 0, one decade below the smallest residual;
/// non-finite residuals sit on the top edge. The note says when either occurs.
LinePlot residual_plot(const std::vector<StepResidual>& per_step,
                       const ResidualPlotOptions& options);

}  // namespace fosssim
