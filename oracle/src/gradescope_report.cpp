#include "gradescope_report.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/text.h"
#include "diagnosis.h"
#include "printable_text.h"

namespace fosssim {

using json = nlohmann::ordered_json;

namespace {

/// A residual for extra_data: the number, or its text when JSON cannot hold it (NaN, inf).
json residual_json(double value) {
  if (std::isfinite(value)) return value;
  return to_text(value);
}

std::string test_output(const SceneResult& r) {
  if (!r.passed()) return printable_text(diagnosis_text(r));
  std::string text = "PASS (" + r.integrator + ", " + std::to_string(r.steps) + " steps)";
  if (r.residuals) {
    text += "\nMaximum Position Residual: " + to_text(r.residuals->max_position) +
            "\nMaximum Velocity Residual: " + to_text(r.residuals->max_velocity) +
            "\nAccumulated Position Residual: " + to_text(r.residuals->accumulated_position) +
            "\nAccumulated Velocity Residual: " + to_text(r.residuals->accumulated_velocity);
  }
  return text + "\n";
}

json extra_data(const SceneResult& r) {
  json data = {{"verdict", verdict_id(r.verdict)}, {"integrator", r.integrator}};
  if (r.residuals) {
    data["max_position_residual"] = residual_json(r.residuals->max_position);
    data["max_velocity_residual"] = residual_json(r.residuals->max_velocity);
    data["accumulated_position_residual"] = residual_json(r.residuals->accumulated_position);
    data["accumulated_velocity_residual"] = residual_json(r.residuals->accumulated_velocity);
  }
  if (r.first_divergence) {
    data["first_divergence_step"] = r.first_divergence->step;
    data["first_divergence_particle"] = r.first_divergence->particle;
    data["first_divergence_object"] = r.first_divergence->object();  // "body" in Theme 3
  }
  return data;
}

std::string plural_points(double points) {
  return to_text(points) + (points == 1.0 ? " point" : " points");
}

}  // namespace

std::string gradescope_json(const GradingRun& run, const GradescopeOptions& options) {
  json tests = json::array();
  double score = 0.0;
  int number = 0;
  for (const SceneResult& r : run.results) {
    const double earned = r.passed() ? options.points_per_scene : 0.0;
    score += earned;
    json test = {{"name", printable_text(r.extra_credit ? "Extra credit: " + r.name : r.name)},
                 {"number", std::to_string(++number)},
                 {"score", earned},
                 {"max_score", r.extra_credit ? 0.0 : options.points_per_scene},
                 {"status", r.passed() ? "passed" : "failed"},
                 {"output", test_output(r)},
                 {"output_format", "text"},
                 {"tags", json::array({r.extra_credit ? "extra-credit" : "regular",
                                       printable_text(r.suite())})},
                 {"visibility", options.visibility},
                 {"extra_data", extra_data(r)}};
    tests.push_back(std::move(test));
  }
  const Tally t = tally(run.results);
  std::string output = "Regular scenes: " + std::to_string(t.regular_passed) + " of " +
                       std::to_string(t.regular) + " passed (" +
                       plural_points(t.regular_passed * options.points_per_scene) + " of " +
                       to_text(t.regular * options.points_per_scene) + ").";
  if (t.extra > 0) {
    output += "\nExtra credit: " + std::to_string(t.extra_passed) + " of " +
              std::to_string(t.extra) + " passed (+" +
              plural_points(t.extra_passed * options.points_per_scene) + ").";
  }
  if (!run.sandboxed) output += std::string("\n") + kNoSandboxNote;
  const json document = {{"score", score},
                         {"execution_time", static_cast<long long>(std::llround(run.wall_seconds))},
                         {"output", output},
                         {"visibility", options.visibility},
                         {"stdout_visibility", "hidden"},
                         {"tests", tests}};
  return document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace fosssim
