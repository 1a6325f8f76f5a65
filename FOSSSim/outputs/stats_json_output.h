#pragma once

#include "outputs/output_format.h"

namespace fosssim {

/// Registry entry "stats-json" (--stats-json FILE): the run's summary (outputs/run_summary.h),
/// written when the run completes; a failed or interrupted run leaves no file.
extern const OutputFormat kStatsJsonOutput;

}  // namespace fosssim
