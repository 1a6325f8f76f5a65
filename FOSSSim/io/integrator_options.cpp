#include "io/integrator_options.h"

#include <initializer_list>
#include <string>

namespace fosssim {

namespace {

/// The optional attribute `name` as one of `choices`; the first choice is the default.
int read_choice(ElementReader& reader, const char* name,
                std::initializer_list<const char*> choices) {
  const std::string value = reader.text_or_empty(name);
  if (value.empty()) return 0;
  int index = 0;
  std::string expected;
  for (const char* choice : choices) {
    if (value == choice) return index;
    expected += (index == 0 ? "" : " or ") + std::string("\"") + choice + "\"";
    ++index;
  }
  reader.fail(name, "must be " + expected + ", found \"" + value + "\"");
}

}  // namespace

void read_integrator_options(ElementReader& reader, IntegratorSettings& settings) {
  if (settings.kind == IntegratorKind::kLocalGlobal) {
    LocalGlobalSettings& lg = settings.local_global;
    if (reader.has("iterations")) {
      lg.iterations = reader.integer("iterations");
      if (lg.iterations < 1)
        reader.fail("iterations", "must be at least 1, found " + std::to_string(lg.iterations));
    }
    lg.tolerance = reader.non_negative_or("tolerance", lg.tolerance);
    lg.pins = read_choice(reader, "pins", {"elimination", "penalty"}) == 0 ? PinMethod::kElimination
                                                                           : PinMethod::kPenalty;
    if (reader.has("penalty")) lg.penalty_weight = reader.positive("penalty");
    constexpr LinearSolverChoice kSolvers[] = {
        LinearSolverChoice::kAuto, LinearSolverChoice::kDense, LinearSolverChoice::kSparse};
    lg.solver = kSolvers[read_choice(reader, "solver", {"auto", "dense", "sparse"})];
  } else if (settings.kind == IntegratorKind::kLinearlyImplicitEuler) {
    settings.linearly_implicit.project_hessian =
        read_choice(reader, "hessian", {"exact", "projected"}) == 1;
  }
}

}  // namespace fosssim
