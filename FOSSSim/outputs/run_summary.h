#pragma once
// A machine-readable summary of a run (schema "fosssim-run-stats", docs/command-line.md, 'Run
// summaries'): steps, solver statistics, collisions per step, energy drift and timings. Fed
// every state of a run; written by --stats-json and returned by the Python module's
// Simulation.stats().

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "core/integrators/integrator.h"
#include "core/scene.h"
#include "core/step/step_record.h"

namespace fosssim {

/// Totals a run's states, step records and solver reports as they come.
class RunSummary {
 public:
  /// The version of the schema json() writes; raised whenever a field changes meaning or
  /// disappears (added fields keep it).
  static constexpr int kSchemaVersion = 1;

  /// A summary of a run of `scene`, which must outlive it.
  explicit RunSummary(const Scene& scene) : scene_(scene) {}

  /// Takes the next state: the initial one (record null), then one per step with the step's
  /// record, each with the run's integrator (null: no solver statistics). The integrator's
  /// running totals are counted from the initial state on, so work done before it (a
  /// factorization in precompute, the steps before Python's set_state) is not.
  void add(const State& state, const StepRecord* record, const Integrator* integrator);

  /// Steps added so far.
  std::int64_t steps() const { return steps_; }

  /// The summary as JSON text (two-space indents, keys in a fixed order, a final newline).
  /// Everything but the "timings" object is a function of the scene and the states alone, so
  /// two runs of one scene give the same bytes outside it.
  std::string json() const;

 private:
  using Clock = std::chrono::steady_clock;

  const Scene& scene_;
  std::optional<Clock::time_point> started_;
  Clock::time_point last_;
  double start_time_ = 0.0, end_time_ = 0.0;
  std::int64_t steps_ = 0;
  // Solver statistics.
  std::string iterations_of_;
  std::int64_t iterations_ = 0;
  int max_step_iterations_ = 0;
  SolverReport first_report_, last_report_;  // the totals at the initial state and now
  // Collisions.
  std::int64_t collisions_ = 0, max_step_collisions_ = 0, steps_with_collisions_ = 0;
  // Energy: total (kinetic + potential) of the initial state, the last, and the extremes.
  std::optional<double> initial_energy_;
  double final_energy_ = 0.0, min_energy_ = 0.0, max_energy_ = 0.0, max_drift_ = 0.0;
};

}  // namespace fosssim
