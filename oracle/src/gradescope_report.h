#pragma once
// Gradescope's results.json (autograder specification: "Output format", "Test case status",
// "Controlling test case visibility"), one test per scene.

#include <string>

#include "grading_run.h"

namespace fosssim {

struct GradescopeOptions {
  double points_per_scene = 1.0;
  /// Gradescope's visibility of every test: "visible", "hidden", "after_due_date" or
  /// "after_published".
  std::string visibility = "visible";
};

/// The results.json text. Each regular scene is a test worth `points_per_scene`
/// (max_score = points_per_scene, score = points_per_scene if it passes, else 0). Each
/// extra-credit scene is a test named "Extra credit: <scene>" with max_score 0 and score
/// points_per_scene if it passes: it adds to the top-level "score" without raising the regular
/// maximum. Every test carries an explicit "status" ("passed" or "failed"), since a max_score of
/// 0 would otherwise show as passed. "output" holds the verdict and, for a failure, the
/// diagnosis; "extra_data" the verdict identifier and the residuals.
std::string gradescope_json(const GradingRun& run, const GradescopeOptions& options = {});

}  // namespace fosssim
