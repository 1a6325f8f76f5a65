#include <iostream>

#include "app/commands.h"
#include "app/interrupt.h"
#include "app/progress_bar.h"
#include "cli/exit_codes.h"
#include "grading/grader.h"
#include "grading/step_grader.h"
#include "io/trajectory_file.h"

namespace fosssim {

int run_grading(const Scene& scene, const Options& options) {
  TrajectoryReader file = open_trajectory(options.input, scene.model);
  ProgressBar progress("grading", scene.model.num_steps(),
                       choose_progress_style(options.progress, options.quiet),
                       options.progress_every);
  GradeReport report;
  try {
    StepGrader grader = StepGrader::open(scene, file);
    while (grader.grade_next_step()) {
      progress.update(grader.steps_graded());
      if (interrupt_requested()) {
        progress.finish();
        std::cerr << "FOSSSim: interrupted at step " << grader.steps_graded()
                  << " of the grading; no report and no residual file were written\n";
        return kExitInterrupted;
      }
    }
    report = grader.report();
  } catch (const Error& error) {
    progress.finish();
    throw Error(error.kind(), options.input + ": " + error.what());
  }
  progress.finish();
  return report_grade(scene, options, report);
}

int report_grade(const Scene& scene, const Options& options, const GradeReport& report) {
  print_grade_report(std::cout, report);
  write_residual_file(options.residual_file, report);
  if (!report.passed()) {
    std::cerr << describe_failure(report, scene.model.dim);
    return kExitGradingFailed;
  }
  return kExitOk;
}

}  // namespace fosssim
