#pragma once
// A small graded run with every kind of result, for the report tests.

#include <limits>

#include "grading_run.h"

namespace fosssim::testing {

/// A reason full of characters that XML and JSON must escape, plus raw control bytes and an
/// invalid UTF-8 byte that the writers must make printable.
inline const std::string kNastyReason = "exploded <at> step & \"quoted\" 'single' \xce\xbb\x01\xff";

inline SceneResult sample_result(const std::string& name, Verdict verdict, bool extra = false) {
  SceneResult r;
  r.name = name;
  r.extra_credit = extra;
  r.integrator = "explicit-euler";
  r.dim = 2;
  r.particles = 4;
  r.steps = 50;
  r.dt = 0.01;
  r.verdict = verdict;
  r.run_seconds = 0.25;
  r.grade_seconds = 0.125;
  if (verdict == Verdict::kPassed || verdict == Verdict::kFailed) {
    r.residuals = Residuals{0.0, 0.0, 0.0, 0.0};
  }
  if (verdict == Verdict::kFailed) {
    r.residuals = Residuals{3e-9, 0.0, 1e-9, std::numeric_limits<double>::quiet_NaN()};
    r.first_divergence = DivergencePoint{17, 2, 1e-9, 0.0};
    r.reason =
        "Maximum Position Residual 1e-09 (limit 1e-10); first divergence at step 17, particle 2";
    r.details = "First divergence at step 17, particle 2: position residual 1e-09\n";
  } else if (verdict != Verdict::kPassed) {
    r.reason = kNastyReason;
    r.stderr_tail = "line one\nline <two> & \x07";
  }
  if (verdict == Verdict::kSceneError) r.integrator.clear();
  return r;
}

/// Five scenes in three suites: two regular folders and one extra-credit folder.
inline GradingRun sample_run() {
  GradingRun run;
  run.candidate = "/path/to/student <bin>";
  run.results = {sample_result("assets/a/one.xml", Verdict::kPassed),
                 sample_result("assets/a/two.xml", Verdict::kFailed),
                 sample_result("assets/b/three.xml", Verdict::kCrashed),
                 sample_result("assets/b/four.xml", Verdict::kSceneError),
                 sample_result("extra/c/five.xml", Verdict::kPassed, true),
                 sample_result("extra/c/six.xml", Verdict::kTimedOut, true)};
  for (const SceneResult& r : run.results) run.scenes.push_back({r.name, r.extra_credit});
  run.wall_seconds = 2.6;
  return run;
}

}  // namespace fosssim::testing
