#include <iostream>

#include "app/commands.h"
#include "app/interrupt.h"
#include "app/progress_bar.h"
#include "cli/exit_codes.h"
#include "grading/grader.h"
#include "grading/rigid_grader.h"
#include "grading/step_grader.h"
#include "io/trajectory_file.h"

namespace fosssim {

namespace {
/// Theme 3: the course's rigid-body report and residual file.
int run_rigid_grading(const Scene& scene, const Options& options) {
  RigidGradeReport report;
  try {
    report = grade_rigid_trajectory(scene, options.input);
  } catch (const Error& error) {
    throw Error(error.kind(), options.input + ": " + error.what());
  }
  print_rigid_grade_report(std::cout, report);
  write_rigid_residual_file(options.residual_file, report);
  return report.passed() ? kExitOk : kExitGradingFailed;
}
}  // namespace

int run_grading(const Scene& scene, const Options& options) {
  if (scene.model.rigid_bodies) return run_rigid_grading(scene, options);
  TrajectoryReader file = open_trajectory(options.input, scene.model);
  ProgressBar progress("grading", scene.model.num_steps(),
                       choose_progress_style(options.progress, options.quiet),
                       options.progress_every);
  GradeReport report;
  try {
    StepGrader grader =
        StepGrader::open(scene, file, std::nullopt, Cancellation(&interrupt_requested));
    const auto interrupted = [&] {
      progress.finish();
      std::cerr << "FOSSSim: interrupted at step " << grader.steps_graded()
                << " of the grading; no report and no residual file were written\n";
      return kExitInterrupted;
    };
    try {
      while (grader.grade_next_step()) {
        progress.update(grader.steps_graded());
        if (interrupt_requested()) return interrupted();
      }
    } catch (const StepCancelled&) {
      return interrupted();  // a signal arrived inside a reference step
    }
    report = grader.report();
  } catch (const Error& error) {
    progress.finish();
    throw Error(error.kind(), options.input + ": " + error.what());
  }
  progress.finish();
  if (report.frames_after_last_step > 0) {
    std::cerr << "FOSSSim: note: " << options.input << " holds " << report.frames_after_last_step
              << " frame" << (report.frames_after_last_step == 1 ? "" : "s")
              << " after the scene's last step; not graded (the course's Theme 4 program "
                 "ignores them)\n";
  }
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
