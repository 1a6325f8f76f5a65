#include "outputs/run_summary.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/analysis/energy.h"

namespace fosssim {

void RunSummary::add(const State& state, const StepRecord* record, const Integrator* integrator) {
  last_ = Clock::now();
  if (!started_) {
    started_ = last_;
    start_time_ = state.time;
  } else {
    ++steps_;
  }
  end_time_ = state.time;

  if (record != nullptr) {
    const auto collisions = static_cast<std::int64_t>(record->collisions.size());
    collisions_ += collisions;
    max_step_collisions_ = std::max(max_step_collisions_, collisions);
    if (collisions > 0) ++steps_with_collisions_;
  }
  if (integrator != nullptr) {
    last_report_ = integrator->solver_report();
    if (record == nullptr) first_report_ = last_report_;
    iterations_of_ = std::string(last_report_.iterations_of);
    if (record != nullptr) {  // a step: its iterations count
      iterations_ += last_report_.last_step_iterations;
      max_step_iterations_ = std::max(max_step_iterations_, last_report_.last_step_iterations);
    }
  }

  const double energy = compute_energies(scene_.model, state).total();
  if (!initial_energy_) {
    initial_energy_ = energy;
    min_energy_ = max_energy_ = energy;
  }
  final_energy_ = energy;
  min_energy_ = std::min(min_energy_, energy);
  max_energy_ = std::max(max_energy_, energy);
  max_drift_ = std::max(max_drift_, std::abs(energy - *initial_energy_));
}

namespace {

using Json = nlohmann::ordered_json;

/// The threads this process has now (the entries of /proc/self/task), or nothing where the
/// system does not say (no /proc).
std::optional<std::int64_t> process_threads() {
  std::error_code error;
  std::filesystem::directory_iterator task("/proc/self/task", error);
  if (error) return std::nullopt;
  std::int64_t count = 0;
  for (; task != std::filesystem::directory_iterator(); task.increment(error)) {
    if (error) return std::nullopt;
    ++count;
  }
  return count;
}

/// A number, or null when it is not finite (JSON has no NaN or infinity).
Json number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

/// The counts of `now` minus those of `before`.
SolveStatistics since(const SolveStatistics& now, const SolveStatistics& before) {
  SolveStatistics s = now;
  s.solves -= before.solves;
  s.factorizations -= before.factorizations;
  s.analyses -= before.analyses;
  s.krylov_iterations -= before.krylov_iterations;
  s.lu_factorizations -= before.lu_factorizations;
  s.ldlt_factorizations -= before.ldlt_factorizations;
  s.single_precision_factorizations -= before.single_precision_factorizations;
  s.direct_fallbacks -= before.direct_fallbacks;
  return s;
}

Json linear_solves(const SolveStatistics& s) {
  Json out;
  out["solves"] = s.solves;
  out["factorizations"] = s.factorizations;
  out["analyses"] = s.analyses;
  out["krylov_iterations"] = s.krylov_iterations;
  out["lu_factorizations"] = s.lu_factorizations;
  out["ldlt_factorizations"] = s.ldlt_factorizations;
  out["single_precision_factorizations"] = s.single_precision_factorizations;
  out["direct_fallbacks"] = s.direct_fallbacks;
  return out;
}

}  // namespace

std::string RunSummary::json() const {
  const SceneModel& model = scene_.model;
  const double steps = static_cast<double>(std::max<std::int64_t>(steps_, 1));
  Json out;
  out["schema"] = "fosssim-run-stats";
  out["version"] = kSchemaVersion;
  out["scene"] = scene_.source;
  out["dim"] = model.dim;
  out["bodies"] = model.rigid_bodies ? "rigid-bodies" : "particles";
  out["integrator"] = {{"method", std::string(model.integrator.method->name)},
                       {"dt", model.integrator.dt}};
  out["steps"] = steps_;
  out["time"] = {{"start", start_time_}, {"end", end_time_}};

  Json solver;
  if (iterations_of_.empty()) {
    solver["iterations"] = nullptr;
  } else {
    solver["iterations"] = {{"of", iterations_of_},
                            {"total", iterations_},
                            {"max_per_step", max_step_iterations_},
                            {"mean_per_step", static_cast<double>(iterations_) / steps}};
  }
  solver["line_search_steps"] = last_report_.line_search_steps - first_report_.line_search_steps;
  solver["factorizations"] = last_report_.factorizations - first_report_.factorizations;
  solver["linear_solves"] = last_report_.linear_solves
                                ? linear_solves(since(*last_report_.linear_solves,
                                                      first_report_.linear_solves.value_or(
                                                          SolveStatistics{})))
                                : Json(nullptr);
  out["solver"] = solver;

  out["collisions"] = {{"total", collisions_},
                       {"max_per_step", max_step_collisions_},
                       {"steps_with_collisions", steps_with_collisions_},
                       {"mean_per_step", static_cast<double>(collisions_) / steps}};

  const double initial = initial_energy_.value_or(0.0);
  const bool relative = initial != 0.0 && std::isfinite(initial);
  out["energy"] = {
      {"initial", number(initial)},
      {"final", number(final_energy_)},
      {"min", number(min_energy_)},
      {"max", number(max_energy_)},
      {"drift", number(final_energy_ - initial)},
      {"max_drift", number(max_drift_)},
      {"relative_drift",
       relative ? number((final_energy_ - initial) / std::abs(initial)) : Json(nullptr)},
      {"max_relative_drift", relative ? number(max_drift_ / std::abs(initial)) : Json(nullptr)},
      // Defined for every run: relative where E0 can scale it, else absolute, and says which.
      {"normalized_drift",
       number(relative ? (final_energy_ - initial) / std::abs(initial) : final_energy_ - initial)},
      {"max_normalized_drift", number(relative ? max_drift_ / std::abs(initial) : max_drift_)},
      {"normalized_by", relative ? "initial" : "none"},
  };

  const double seconds =
      started_ ? std::chrono::duration<double>(last_ - *started_).count() : 0.0;
  const std::optional<std::int64_t> threads = process_threads();
  out["timings"] = {{"wall_seconds", seconds},
                    {"seconds_per_step", seconds / steps},
                    {"threads", threads ? Json(*threads) : Json(nullptr)}};
  return out.dump(2) + "\n";
}

}  // namespace fosssim
