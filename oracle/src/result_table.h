#pragma once
// The terminal report: a table of every scene, the reasons of the failures, and the totals.

#include <ostream>

#include "grading_run.h"

namespace fosssim {

/// Prints one row per scene (scene, integrator, verdict, maximum position and velocity residual,
/// first failing step and particle, seconds), regular scenes first and extra credit under its own
/// heading; then each failure's reason; then the totals and the wall time.
void print_result_table(std::ostream& out, const GradingRun& run);

/// One progress line for a finished scene: "[ 3/12] PASS       assets/t1m1/x.xml  (0.41 s)".
std::string progress_line(const SceneResult& result, std::size_t done, std::size_t total);

}  // namespace fosssim
