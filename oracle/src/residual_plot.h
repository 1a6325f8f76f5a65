#pragma once
// A self-contained SVG line plot of a trajectory's per-step residuals over time, on a
// logarithmic axis, with the course's maximum limit and the first divergence marked.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grading/grader.h"

namespace fosssim {

struct ResidualPlotOptions {
  std::string title;
  double dt = 0.01;                         ///< seconds per step, for the time axis
  double limit = 1e-10;                     ///< the maximum limit, drawn as a dashed line
  std::optional<std::int64_t> marked_step;  ///< the first divergence, drawn as a vertical line
  int max_points = 1500;                    ///< longer runs are reduced to this many columns, each
                                            ///< keeping its largest residual
};

/// The SVG document (UTF-8 text): max over particles of the position and of the velocity
/// residual at every step, y = log10(residual). Exact zeros get a bottom line of their own,
/// labelled 0, one decade below the smallest residual; non-finite ones sit on the top edge.
std::string residual_plot_svg(const std::vector<StepResidual>& per_step,
                              const ResidualPlotOptions& options);

}  // namespace fosssim
