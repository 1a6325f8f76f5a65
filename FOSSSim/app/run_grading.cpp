#include <iostream>

#include "app/commands.h"
#include "app/progress_bar.h"
#include "cli/exit_codes.h"
#include "grading/grader.h"
#include "io/trajectory_file.h"

namespace fosssim {

int run_grading(const Scene& scene, const Options& options) {
  auto file = open_trajectory(options.input, scene.model);
  if (!file) {
    std::cerr << "FOSSSim: error: " << file.error() << "\n";
    return kExitBadInput;
  }
  ProgressBar progress("grading", scene.model.num_steps(), !options.quiet && stderr_is_terminal());
  auto report =
      grade_trajectory(scene, *file, GradingCriteria{},
                       [&progress](std::int64_t done, std::int64_t) { progress.update(done); });
  progress.finish();
  if (!report) {
    std::cerr << "FOSSSim: error: " << options.input << ": " << report.error() << "\n";
    return kExitBadInput;
  }
  return report_grade(scene, options, *report);
}

int report_grade(const Scene& scene, const Options& options, const GradeReport& report) {
  print_grade_report(std::cout, report);
  try {
    write_residual_file(options.residual_file, report);
  } catch (const std::runtime_error& error) {
    std::cerr << "FOSSSim: error: " << error.what() << "\n";
    return kExitIoError;
  }
  if (!report.passed()) {
    std::cerr << describe_failure(report, scene.model.dim);
    return kExitGradingFailed;
  }
  return kExitOk;
}

}  // namespace fosssim
