#pragma once
// What an integrator's solvers did, for run summaries (FOSSSim --stats-json, the Python
// module's Simulation.stats()): read after each step, so a caller can total and compare.

#include <cstdint>
#include <optional>
#include <string_view>

#include "core/solvers/step_solver.h"

namespace fosssim {

/// The solver statistics an integrator records (Integrator::solver_report). Methods that
/// solve nothing report the defaults.
struct SolverReport {
  /// What the iterations are: "newton", "quasi-newton", "local-global"; empty for methods
  /// that do not iterate (the count below is then 0).
  std::string_view iterations_of = {};
  /// Iterations the last step took (of its last solve, when it solved more than once).
  int last_step_iterations = 0;
  /// Steps so far that plain Newton could not solve and its line-search fall-back did
  /// (implicit Euler).
  std::int64_t line_search_steps = 0;
  /// Factorizations of a constant matrix so far (local/global, quasi-Newton's Q).
  std::int64_t factorizations = 0;
  /// What the step systems' solver (StepSolver) did so far, for methods that use it; nothing
  /// for the course's dense LU of small 2D systems.
  std::optional<SolveStatistics> linear_solves = {};
};

}  // namespace fosssim
